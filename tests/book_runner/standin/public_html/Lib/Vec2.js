"use strict";
// A plain 2D vector; each operation makes a new one.
var Vec2 = function (x, y) {
    this.x = x;
    this.y = y;
};
Vec2.prototype.add = function (other) {
    return new Vec2(this.x + other.x, this.y + other.y);
};
Vec2.prototype.scale = function (factor) {
    return new Vec2(this.x * factor, this.y * factor);
};
