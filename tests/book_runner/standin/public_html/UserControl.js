"use strict";
// A few of the book's keys: digits select, K pushes down, comma starts and stops the
// motion, F makes a rectangle of random size at the selected shape and throws it, X
// removes every shape after the first one (so the echo of a shape past the end throws),
// and Z never returns (so the runner's time limit has something to stop).
var gObjectNum = 0;
function userControl(event) {
    var code = window.event ? event.keyCode : event.which;
    var shapes = gEngine.Core.mAllObjects;
    if (code >= 48 && code <= 57 && code - 48 < shapes.length) {
        gObjectNum = code - 48;
    }
    if (code === 75) {
        shapes[gObjectNum].mVelocity.y += 1;
    }
    if (code === 188) {
        gEngine.Core.mMovement = !gEngine.Core.mMovement;
    }
    if (code === 70) {
        var at = shapes[gObjectNum].mCenter;
        var made = new Rectangle(new Vec2(at.x, at.y), Math.random() * 30 + 10, Math.random() * 30 + 10);
        made.mVelocity = new Vec2(Math.random() * 300 - 150, Math.random() * 300 - 150);
    }
    if (code === 88) {
        shapes.splice(1, shapes.length);
    }
    while (code === 90) {
        gObjectNum = 0;
    }
}
