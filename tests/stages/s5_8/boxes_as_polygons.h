#pragma once
// A scene's moving boxes given as polygons: each rectangle that is not static becomes the
// 4-gon of its corners, so that the same pyramid can be run as the book's rectangles and
// as polygons and the two compared (the test s5_8_test.cpp, build/polygons_bench,
// build/polygon_scenes and build/gap_study).

#include <vector>

#include "scene_io.h"

namespace test {

// A w x h box's corners about its middle, as a scene gives a polygon's.
inline std::vector<engine::Vec2> boxCorners(double w, double h) {
    return {{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
}

inline void boxesAsPolygons(engine::Scene& scene) {
    for (engine::BodyDescription& body : scene.bodies) {
        if (body.shape != engine::ShapeType::Rectangle || body.mass == 0.0) continue;
        body.shape = engine::ShapeType::Polygon;
        body.vertices = boxCorners(body.width, body.height);
    }
}

}  // namespace test
