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
// with ever larger ids, and leave it without reordering it: the list is sorted by id,
// and so is `ids`, the list's ids in its order, which the search reads: one array,
// where reading each shape's id would fetch a shape from anywhere in memory. Each id is
// at least one more than the one before, so `id` is at most id - ids[0] places in: just
// there while no shape has left, and the search looks no further.
const RigidShape* shapeWithId(ShapeList shapes, const std::vector<BodyId>& ids, BodyId id) {
    if (ids.empty() || id < ids.front()) return nullptr;
    const std::size_t most = std::min<std::size_t>(id - ids.front(), ids.size() - 1);
    if (ids[most] == id) return shapes[most].get();
    const auto found = std::lower_bound(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(most), id);
    return *found == id ? shapes[static_cast<std::size_t>(found - ids.begin())].get() : nullptr;
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
    first_report_.clear();
    touching_.clear();
    events_.clear();
    pending_.clear();
}

void ContactEvents::startStep(long step) {
    step_ = step;
    events_.clear();
    events_.swap(pending_);
}

std::size_t ContactEvents::slotOf(PairIds pair) const {
    // Two odd multipliers spread consecutive ids over the table, and the high bits, the
    // best mixed, are folded down into the low ones that pick the slot.
    std::uint64_t hash = pair.first * 0x9E3779B97F4A7C15ULL ^ pair.second * 0xC2B2AE3D27D4EB4FULL;
    hash ^= hash >> 32;
    return static_cast<std::size_t>(hash) & (first_report_.size() - 1);
}

void ContactEvents::holdReports(std::size_t reports) {
    std::size_t size = 64;
    while (size < 2 * reports) size *= 2;
    first_report_.assign(size, 0);
    for (std::size_t k = 0; k < found_.size(); ++k) {
        std::size_t slot = slotOf(found_[k].pair);
        while (first_report_[slot] != 0) slot = (slot + 1) & (size - 1);
        first_report_[slot] = static_cast<std::uint32_t>(k + 1);
    }
}

bool ContactEvents::firstReport(PairIds pair) {
    if (2 * (found_.size() + 1) > first_report_.size()) holdReports(2 * (found_.size() + 1));
    for (std::size_t slot = slotOf(pair);; slot = (slot + 1) & (first_report_.size() - 1)) {
        const std::uint32_t entry = first_report_[slot];
        if (entry == 0) {
            first_report_[slot] = static_cast<std::uint32_t>(found_.size() + 1);
            return true;
        }
        if (found_[entry - 1].pair == pair) return false;
    }
}

void ContactEvents::touching(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (!kept() || !firstReport({a.id(), b.id()})) return;
    // The shapes come in list order, which is id order: the normal already points from
    // the smaller id to the larger.
    const Vec2 point = (info.start() + info.end()) * 0.5;
    const double approach = -(surfaceVelocity(b, point) - surfaceVelocity(a, point)).dot(info.normal());
    found_.push_back({{a.id(), b.id()}, point, info.normal(), approach});
}

void ContactEvents::sensed(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (a.isSensor() && b.isSensor()) return;
    const std::size_t reports = found_.size();
    touching(a, b, info);
    if (found_.size() > reports) found_.back().sensor = true;
}

void ContactEvents::crossed(const RigidShape& mover, const RigidShape& sensor, Vec2 point, Vec2 direction) {
    if (!kept() || !firstReport({std::min(mover.id(), sensor.id()), std::max(mover.id(), sensor.id())})) return;
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
    // found_ holds the first report of each pair (firstReport), in the order found.
    std::sort(found_.begin(), found_.end(), by_pair);
    // A shape removed at the end of the step (out of bounds) touches nothing.
    ids_.clear();
    for (const auto& shape : shapes) ids_.push_back(shape->id());
    std::erase_if(found_, [&](const Touch& touch) {
        return !shapeWithId(shapes, ids_, touch.pair.first) || !shapeWithId(shapes, ids_, touch.pair.second);
    });
    // Into the buffer of the step before last, whose memory is kept: a list of a rain's
    // pairs, made new each step, came fresh from the system each time, page by page.
    std::vector<Touch>& now = next_;
    now.clear();
    now.reserve(found_.size() + touching_.size());
    auto before = touching_.begin();
    auto found = found_.begin();
    while (before != touching_.end() || found != found_.end()) {
        if (found == found_.end() || (before != touching_.end() && before->pair < found->pair)) {
            // Not found this step: still touching if both its shapes rest, since then no
            // pass tested it, or if the step before found it; otherwise it has ended.
            const RigidShape* a = shapeWithId(shapes, ids_, before->pair.first);
            const RigidShape* b = shapeWithId(shapes, ids_, before->pair.second);
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
    std::fill(first_report_.begin(), first_report_.end(), 0);
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
