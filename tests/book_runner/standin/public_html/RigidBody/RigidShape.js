"use strict";
// What every stand-in shape has: the fields the runner reads and the keys change.
// The shape joins the world's list as it is made, as the book's shapes do.
function RigidShape(center, mass, friction, restitution) {
    this.mCenter = center;
    this.mAngle = 0;
    this.mVelocity = new Vec2(0, 0);
    this.mAngularVelocity = 0;
    this.mFriction = friction === undefined ? 0.8 : friction;
    this.mRestitution = restitution === undefined ? 0.2 : restitution;
    var m = mass === undefined ? 1 : mass;
    this.mInvMass = m === 0 ? 0 : 1 / m;
    gEngine.Core.mAllObjects.push(this);
}
RigidShape.prototype.move = function (offset) {
    this.mCenter = this.mCenter.add(offset);
};
RigidShape.prototype.rotate = function (angle) {
    this.mAngle += angle;
};
// Static shapes (inverse mass 0) stay where they are.
RigidShape.prototype.gravity = function () {
    return this.mInvMass === 0 ? new Vec2(0, 0) : gEngine.Core.mGravity;
};
