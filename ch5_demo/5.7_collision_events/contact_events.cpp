#include "contact_events.h"

#include <algorithm>

namespace engine {

namespace {

// The velocity of the shape's point at `point`: its centre's plus the spin's w x r.
Vec2 surfaceVelocity(const RigidShape& shape, Vec2 point) {
    const Vec2 arm = point - shape.center();
    const double w = shape.angularVelocity();
    return shape.velocity() + Vec2{-w * arm.y, w * arm.x};
}

// The shape with id `id`, or nullptr when it is gone. Shapes join the list at its end
// with ever larger ids, and leave it without reordering it: the list is sorted by id.
const RigidShape* shapeWithId(ShapeList shapes, BodyId id) {
    const auto found = std::lower_bound(shapes.begin(), shapes.end(), id,
                                        [](const auto& shape, BodyId wanted) { return shape->id() < wanted; });
    return found != shapes.end() && (*found)->id() == id ? found->get() : nullptr;
}

}  // namespace

std::string_view kindName(EventKind kind) {
    switch (kind) {
        case EventKind::begin: return "begin";
        case EventKind::end: return "end";
        case EventKind::hit: return "hit";
    }
    return "?";
}

void ContactEvents::keep(EventReader reader, bool on) {
    const auto bit = static_cast<unsigned>(reader);
    if (on && !kept() && step_ > 0) taking_in_ = true;
    readers_ = on ? readers_ | bit : readers_ & ~bit;
    if (kept()) return;
    taking_in_ = false;
    recent_.clear();
    found_.clear();
    touching_.clear();
    events_.clear();
    pending_.clear();
}

void ContactEvents::startStep(long step) {
    step_ = step;
    events_.clear();
    events_.swap(pending_);
}

void ContactEvents::touching(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (!kept()) return;
    // The shapes come in list order, which is id order: the normal already points from
    // the smaller id to the larger.
    const Vec2 point = (info.start() + info.end()) * 0.5;
    const double approach = -(surfaceVelocity(b, point) - surfaceVelocity(a, point)).dot(info.normal());
    found_.push_back({{a.id(), b.id()}, point, info.normal(), approach});
}

void ContactEvents::sensed(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (a.isSensor() && b.isSensor()) return;
    touching(a, b, info);
    if (kept()) found_.back().sensor = true;
}

void ContactEvents::crossed(const RigidShape& mover, const RigidShape& sensor, Vec2 point, Vec2 direction) {
    if (!kept()) return;
    // Named smaller id first, the normal from it to the other: along the motion when
    // the mover is the first of the pair, against it otherwise.
    const bool mover_first = mover.id() < sensor.id();
    const Vec2 normal = mover_first ? direction : direction * -1.0;
    const RigidShape& a = mover_first ? mover : sensor;
    const RigidShape& b = mover_first ? sensor : mover;
    const double approach = -(surfaceVelocity(b, point) - surfaceVelocity(a, point)).dot(normal);
    found_.push_back({{a.id(), b.id()}, point, normal, approach, 0, true});
}

ContactEvent ContactEvents::eventOf(EventKind kind, const Touch& touch) const {
    return {.step = step_,
            .kind = kind,
            .id_a = touch.pair.first,
            .id_b = touch.pair.second,
            .point = touch.point,
            .normal = touch.normal,
            .speed = kind == EventKind::hit ? touch.speed : 0.0};
}

void ContactEvents::endStep(ShapeList shapes, double hit_speed) {
    if (!kept()) return;
    const auto by_pair = [](const Touch& x, const Touch& y) { return x.pair < y.pair; };
    const auto same_pair = [](const Touch& x, const Touch& y) { return x.pair == y.pair; };
    // The book's passes report a pair in every pass that finds it: the first report is
    // the one from before anything resolved it, with the speed the pair met at.
    std::stable_sort(found_.begin(), found_.end(), by_pair);
    found_.erase(std::unique(found_.begin(), found_.end(), same_pair), found_.end());
    // A shape removed at the end of the step (out of bounds) touches nothing.
    std::erase_if(found_, [&](const Touch& touch) {
        return !shapeWithId(shapes, touch.pair.first) || !shapeWithId(shapes, touch.pair.second);
    });
    std::vector<Touch> now;
    now.reserve(found_.size() + touching_.size());
    auto before = touching_.begin();
    auto found = found_.begin();
    while (before != touching_.end() || found != found_.end()) {
        if (found == found_.end() || (before != touching_.end() && before->pair < found->pair)) {
            // Not found this step: still touching if both its shapes rest, since then no
            // pass tested it, or if the step before found it; otherwise it has ended.
            const RigidShape* a = shapeWithId(shapes, before->pair.first);
            const RigidShape* b = shapeWithId(shapes, before->pair.second);
            if (a && b && a->isResting() && b->isResting()) {
                now.push_back(*before);
                now.back().missed = 0;  // asleep it is not missed, it is not looked for
            } else if (a && b && before->missed + 1 < kMissedSteps) {
                now.push_back(*before);
                ++now.back().missed;
            } else {
                events_.push_back(eventOf(EventKind::end, *before));
            }
            ++before;
        } else if (before == touching_.end() || found->pair < before->pair) {
            events_.push_back(eventOf(EventKind::begin, *found));
            if (!found->sensor && found->speed > hit_speed) events_.push_back(eventOf(EventKind::hit, *found));
            now.push_back(*found);
            ++found;
        } else {
            now.push_back(*found);  // touching still: where it touches now
            ++before;
            ++found;
        }
    }
    touching_.swap(now);
    found_.clear();
    if (taking_in_) {
        // The first step heard: what touches was touching already (nothing could end).
        events_.clear();
        taking_in_ = false;
    }
    std::erase_if(recent_, [this](const ContactEvent& event) { return event.step <= step_ - kShownSteps; });
    recent_.insert(recent_.end(), events_.begin(), events_.end());
}

void ContactEvents::shapeLeaves(BodyId id) {
    if (!kept()) return;
    std::erase_if(touching_, [&](const Touch& touch) {
        if (touch.pair.first != id && touch.pair.second != id) return false;
        pending_.push_back(eventOf(EventKind::end, touch));
        return true;
    });
}

}  // namespace engine
