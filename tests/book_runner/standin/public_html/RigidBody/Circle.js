"use strict";
// A circle moves with its old velocity, then takes gravity (explicit Euler): the one
// planted difference from our stages, which the tests find with first_divergence.
var Circle = function (center, radius, mass, friction, restitution) {
    RigidShape.call(this, center, mass, friction, restitution);
    this.mType = "Circle";
    this.mRadius = radius;
};
Circle.prototype = Object.create(RigidShape.prototype);
Circle.prototype.update = function (dt) {
    this.move(this.mVelocity.scale(dt));
    this.mVelocity = this.mVelocity.add(this.gravity().scale(dt));
    this.rotate(this.mAngularVelocity * dt);
};
