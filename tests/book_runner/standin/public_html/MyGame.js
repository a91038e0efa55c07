"use strict";
// The stand-in's own scene, when no scene file replaces it: one resting box.
function MyGame() {
    var box = new Rectangle(new Vec2(100, 100), 20, 20, 0);
}
