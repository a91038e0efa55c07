"use strict";
// The loop in the book's shape: each animation frame echoes the selected shape, then
// runs one fixed update for every whole step the clock has moved on. The step in
// milliseconds is 1000 * (1 / 60), as in the book: a hair above 1000 / 60.
var gEngine = gEngine || {};
gEngine.Core = (function () {
    var kStep = 1 / 60;
    var kStepMs = 1000 * kStep;
    var canvas = document.getElementById("canvas");
    var context = canvas.getContext("2d");
    var core = {
        mAllObjects: [],
        mGravity: new Vec2(0, 10),
        mMovement: false,
        mWidth: 800,
        mHeight: 450
    };
    var lastMs = Date.now();
    var lagMs = 0;
    var frame = function () {
        requestAnimationFrame(frame);
        var selected = core.mAllObjects[gObjectNum];
        document.getElementById("uiEchoString").innerHTML = "x: " + selected.mCenter.x.toPrecision(3);
        context.clearRect(0, 0, core.mWidth, core.mHeight);
        var now = Date.now();
        lagMs += now - lastMs;
        lastMs = now;
        while (lagMs >= kStepMs) {
            lagMs -= kStepMs;
            gEngine.Physics.collision();
            if (core.mMovement) {
                core.mAllObjects.forEach(function (shape) {
                    shape.update(kStep);
                });
            }
        }
    };
    core.initializeEngineCore = frame;
    return core;
}());
