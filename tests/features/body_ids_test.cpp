// Ids that never change (5.4 on, rigid_shape.h): the world numbers each shape it takes in
// from a counter of its own that only goes up, an id stays with its shape wherever the
// shape moves in the list, and what a step keeps for the next one (warm starting,
// contact_solver.h) names shapes by id. The failure ids prevent: a shape removed and a
// new one made after it, which takes the old one's place in the list and, since the
// allocator hands freed memory out again, often its very address, must not inherit the
// old one's contact impulses.
#include <catch2/catch.hpp>

#include "circle.h"
#include "rectangle.h"
#include "world_fixture.h"

namespace body_ids_test {

namespace {

// Movement on, the sequential impulse solver, warm starting on (its default).
engine::WorldSettings solverWorld() {
    engine::WorldSettings settings = test::world(true);
    settings.solver = engine::SolverKind::sequential_impulse;
    return settings;
}

// A static floor, its top face at y = 430, and a ball of radius 20 lying on it, half a
// pixel deep: the two touch from the first step on.
engine::Rectangle floor() { return engine::Rectangle({400, 440}, 800, 20, {.mass = 0, .friction = 0.6}); }
engine::Circle ball() { return engine::Circle({400, 410.5}, 20, {.mass = 1, .friction = 0.6, .restitution = 0}); }

}  // namespace

TEST_CASE("body ids: each shape taken in gets the next id, keeps it when others leave, and none comes back") {
    test::WorldFixture page(test::world(true));
    page.core.add(floor());
    page.core.add(engine::Circle({100, 200}, 10));
    page.core.add(engine::Circle({300, 200}, 10));
    page.core.add(engine::Circle({500, 200}, 10));
    for (std::size_t i = 0; i < 4; ++i) CHECK(page.core.object(i).id() == i + 1);
    // A shape outside the canvas leaves at the end of the step (remove_out_of_bounds):
    // the shapes after it move up the list, with their ids.
    page.core.object(1).move({-400, 0});
    page.core.update();
    REQUIRE(page.core.objectCount() == 3);
    CHECK(page.core.object(1).id() == 3);
    CHECK(page.core.object(2).id() == 4);
    // The R key's reset keeps the first shapes; a new one never gets an id given before,
    // though it takes a place, and here the very place in the list, that one had.
    page.core.keepFirstObjects(1);
    CHECK(page.core.add(engine::Circle({300, 200}, 10)).id() == 5);
    CHECK(page.core.add(engine::Rectangle({500, 200}, 20, 20)).id() == 6);
    // A shape no world has taken in has none.
    CHECK(engine::Circle({0, 0}, 1).id() == 0);
}

TEST_CASE("body ids: a ball made where a removed one lay starts with no impulses, as in a new world") {
    // One velocity iteration, so that a first guess shows: friction is solved before the
    // normal push, within mu times the normal total as it stands, which is 0 for a
    // contact met for the first time and the last step's total for one warm started.
    engine::WorldSettings settings = solverWorld();
    settings.velocity_iterations = 1;
    test::WorldFixture page(settings);
    page.core.add(floor());
    const engine::RigidShape* old = &page.core.add(ball());
    page.steps(10);
    // At rest on the floor: the contact is found again every step, and warm started.
    REQUIRE(page.core.physics().contactSolver().persistedPointCount() == 1);
    REQUIRE(page.core.physics().contactSolver().contacts().at(0).points[0].normal_impulse > 0);

    // The R key's reset, then a new ball where the old one lay: the same shape, the same
    // place in the list, the same contact key on the floor.
    page.core.keepFirstObjects(1);
    engine::RigidShape& made = page.core.add(ball());
    made.setVelocity({50, 0});  // sliding: friction has something to act on
    // (With the system's allocator the new ball lands at the freed one's address, which
    // is what fooled a solver that named shapes by address; a checking allocator, such
    // as AddressSanitizer's, keeps freed memory back, and the case then only shows that
    // ids, whatever the addresses, keep the two apart.)
    INFO("the new ball " << (&made == old ? "took" : "did not take") << " the old one's address");
    page.steps(1);

    // A world that never had the old ball, stepped once from the same start.
    test::WorldFixture fresh(settings);
    fresh.core.add(floor());
    fresh.core.add(ball()).setVelocity({50, 0});
    fresh.steps(1);

    CHECK(page.core.physics().contactSolver().persistedPointCount() == 0);
    const auto& contacts = page.core.physics().contactSolver().contacts();
    const auto& fresh_contacts = fresh.core.physics().contactSolver().contacts();
    REQUIRE(contacts.size() == 1);
    REQUIRE(fresh_contacts.size() == 1);
    CHECK(contacts[0].id_b == made.id());
    CHECK(contacts[0].points[0].normal_impulse == fresh_contacts[0].points[0].normal_impulse);
    CHECK(contacts[0].points[0].tangent_impulse == fresh_contacts[0].points[0].tangent_impulse);
    CHECK(made.velocity() == fresh.core.object(1).velocity());
    CHECK(made.angularVelocity() == fresh.core.object(1).angularVelocity());
    CHECK(made.center() == fresh.core.object(1).center());
}

}  // namespace body_ids_test
