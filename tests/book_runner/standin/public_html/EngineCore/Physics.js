"use strict";
// No collisions: the pass only counts how often it ran.
var gEngine = gEngine || {};
gEngine.Physics = {
    mPositionalCorrectionFlag: true,
    mPasses: 0,
    collision: function () {
        gEngine.Physics.mPasses += 1;
    }
};
