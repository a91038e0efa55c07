#pragma once
// The book's MyGame.js: the scene the world starts with. Edit it to try another scene,
// or give the program a scene file (--scene FILE, scene_io.h).

#include <optional>
#include <string>
#include <vector>

#include "core.h"
#include "random.h"

namespace engine {

// The cool demo: no borders, so shapes can fall off the canvas and the space never
// crowds. Four static platforms come first (objects 0 to 3):
//   (500, 200) 400 x 20, turned 2.8 rad, friction 0.3, restitution 0: a long slide
//   (200, 400) 400 x 20, friction 1, restitution 0.5: the floor on the left
//   (100, 200) 200 x 20, the default friction and restitution: a ledge
//   (10, 360)  20 x 100, friction 0, restitution 1: a slippery, springy post
// then ten times a rectangle and a circle with random size, mass, friction,
// restitution and velocity, somewhere in the top half of the canvas.
void buildScene(Core& core, browser::Random& random);

// The demo's game (5.7): what a reader of the book builds first with collision events,
// each read after the step (contact_events.h), never inside it.
//   - A zone, a sensor over the left floor, counts the shapes inside it: one more at
//     each begin with it, one fewer at each end.
//   - A shape turns orange at its first contact with another solid shape (a begin).
//   - A goal, a sensor below the long slide's foot on the right, removes every shape
//     that enters it and counts it as scored.
// From 5.8 five random convex polygons follow the book's shapes.
// The book's scene is built as buildScene builds it, with the zone and the goal added
// after its four platforms (objects 4 and 5), so that the R key, which keeps the first
// seven objects, keeps them too; they draw no random number, so the random shapes are
// the book's.
class DemoGame final : public GameLogic {
public:
    DemoGame(Core& core, browser::Random& random);

    void afterStep(Core& core) override;
    std::optional<browser::Color> colourOf(const RigidShape& shape) const override;
    std::string echo() const override;

    BodyId zone() const { return zone_; }
    BodyId goal() const { return goal_; }
    std::size_t insideZone() const { return inside_.size(); }
    int scored() const { return scored_; }

private:
    BodyId zone_ = 0;
    BodyId goal_ = 0;
    std::vector<BodyId> touched_;  // every shape that has met another, sorted
    std::vector<BodyId> inside_;   // in the zone now, sorted
    int scored_ = 0;
};

}  // namespace engine
