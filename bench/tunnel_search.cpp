#include "tunnel_search.h"

#include <cmath>
#include <stdexcept>

#include "bench_world.h"

namespace bench {
namespace {

constexpr double kFirstGuess = 100.0;  // px/s
constexpr double kFastest = 1e8;       // px/s: beyond this nothing is a wall any more

struct Layout {
    std::size_t ball = 0;
    double ball_radius = 0.0;
    double far_side = 0.0;  // x of the wall's far face
};

Layout layout_of(const SceneDescription& scene) {
    Layout layout;
    bool ball_found = false;
    bool wall_found = false;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const bench::BodyDescription& body = scene.bodies[i];
        if (body.mass > 0 && body.shape == bench::Shape::circle && !ball_found) {
            layout.ball = i;
            layout.ball_radius = body.radius;
            ball_found = true;
        } else if (body.mass == 0 && body.shape == bench::Shape::rectangle && !wall_found) {
            layout.far_side = body.center.x + body.width / 2;
            wall_found = true;
        }
    }
    if (!ball_found || !wall_found) throw std::invalid_argument("tunnel scene: needs a moving disc and a static box");
    return layout;
}

}  // namespace

bool ball_passes(Stage stage, const SceneDescription& scene, double speed) {
    const Layout layout = layout_of(scene);
    SceneDescription sent = scene;
    sent.bodies[layout.ball].velocity = {speed, 0.0};
    const double past = layout.far_side + layout.ball_radius;  // centre x once wholly past
    const double distance = past - sent.bodies[layout.ball].center.x;
    const long limit = 2 * static_cast<long>(std::ceil(distance / (speed * scene.world.dt))) + 2;

    const std::unique_ptr<BenchWorld> world = stage_world(stage, sent);
    for (long step = 0; step < limit; ++step) {
        world->run(1);
        const BodyState ball = world->snapshot()[layout.ball];
        if (oracle::center(ball.shape).x > past) return true;
        if (ball.velocity.x < 0) return false;
    }
    return false;
}

double slowest_passing_speed(Stage stage, const SceneDescription& scene, double tolerance) {
    double low = 0.0;  // does not pass (at rest it never gets there)
    double high = kFirstGuess;
    while (!ball_passes(stage, scene, high)) {
        low = high;
        high *= 2;
        if (high > kFastest) throw std::runtime_error("tunnel search: the ball never passes");
    }
    while (high - low > tolerance * high) {
        const double middle = (low + high) / 2;
        (ball_passes(stage, scene, middle) ? high : low) = middle;
    }
    return high;
}

}  // namespace bench
