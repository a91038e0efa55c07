"use strict";
// A rectangle takes gravity first, then moves with its new velocity (symplectic Euler),
// as our stages' shapes do.
var Rectangle = function (center, width, height, mass, friction, restitution) {
    RigidShape.call(this, center, mass, friction, restitution);
    this.mType = "Rectangle";
    this.mWidth = width;
    this.mHeight = height;
};
Rectangle.prototype = Object.create(RigidShape.prototype);
Rectangle.prototype.update = function (dt) {
    this.mVelocity = this.mVelocity.add(this.gravity().scale(dt));
    this.move(this.mVelocity.scale(dt));
    this.rotate(this.mAngularVelocity * dt);
};
