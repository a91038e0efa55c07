#include "contact_events.h"

#include <algorithm>
#include <iterator>
#include <utility>

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
        case EventKind::limit: return "limit";
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
    marks_.clear();
    touches_.clear();
    found_.clear();
    begun_.clear();
    run_.clear();
    last_report_ = {};
    events_.clear();
    pending_.clear();
}

void ContactEvents::startStep(long step) {
    step_ = step;
    events_.clear();
    events_.swap(pending_);
}

// Each report is set against the pairs touching as it comes, without a table to look
// it up in: the reports of one pass come in ascending order of their pairs (the broad
// phase meets a row's partners in ascending order, rows in list order, and the list is
// in id order, see shapeWithId above), and the list of pairs touching is sorted the
// same way. So a pass's reports and the list are walked together, the list's place
// only ever moving forward, as one reads two sorted lists side by side to merge them.
// A report whose pair does not come after the one before (the next pass, the next
// sub-step, a sweep's crossing) starts a new run of reports, and the walk starts again
// from the front.
//
// The step's first report of a pair is the one kept: the book's passes find a pair
// again in each of them, and the first, from before anything resolved it, has the
// speed the pair met at.
void ContactEvents::report(const RigidShape& a, const RigidShape& b, Vec2 point, Vec2 normal, bool sensor) {
    const PairIds pair{a.id(), b.id()};
    // The run's last report is the later of the last one taken here and the last pair
    // the walk has left behind (touching(), below, only moves the walk).
    if (!(last_report_ < pair) || (marks_walked_ > 0 && !(marks_[marks_walked_ - 1].pair < pair))) closeRun();
    last_report_ = pair;
    while (marks_walked_ < marks_.size() && marks_[marks_walked_].pair < pair) ++marks_walked_;
    if (marks_walked_ < marks_.size() && marks_[marks_walked_].pair == pair) {
        // Touching already: no begin, so no approach speed either; only where it touches now.
        const std::size_t k = marks_walked_++;
        if (marks_[k].found) return;
        marks_[k].found = true;
        found_[k] = {point, normal, sensor};
        return;
    }
    while (begun_walked_ < begun_.size() && begun_[begun_walked_].pair < pair) ++begun_walked_;
    if (begun_walked_ < begun_.size() && begun_[begun_walked_].pair == pair) return;
    // New: a begin, and a hit if the surfaces met fast.
    const double approach = -(surfaceVelocity(b, point) - surfaceVelocity(a, point)).dot(normal);
    run_.push_back({pair, {point, normal, sensor}, approach});
}

// A run's new pairs, in ascending order as they came, join the step's others, which the
// next run will walk.
void ContactEvents::closeRun() {
    if (!run_.empty()) {
        next_begun_.clear();
        std::merge(begun_.begin(), begun_.end(), run_.begin(), run_.end(), std::back_inserter(next_begun_),
                   [](const Begin& x, const Begin& y) { return x.pair < y.pair; });
        begun_.swap(next_begun_);
        run_.clear();
    }
    last_report_ = {};  // no pair comes before it: ids start at 1
    marks_walked_ = 0;
    begun_walked_ = 0;
}

// The hot path: the book's passes report a rain of 1000's pairs some 10,000 times a
// step, nearly all of them pairs touching already, so their common case costs a few
// comparisons and no call. A pass that finds the pairs the pass before found finds
// each one the walk's next, or the one after it when the pair between was not found
// this time (its shapes rest, or came apart); and since the walk stands just after the
// run's last report, either comes after it: the run goes on. Anything else is
// report()'s. Where the pair touches is worked out only for the step's first report
// of it.
void ContactEvents::touching(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (!kept()) return;
    // The shapes come in list order, which is id order: the normal already points from
    // the smaller id to the larger.
    const PairIds pair{a.id(), b.id()};
    std::size_t k = marks_walked_;
    if (k < marks_.size() && marks_[k].pair != pair) ++k;
    if (k >= marks_.size() || marks_[k].pair != pair) {
        report(a, b, (info.start() + info.end()) * 0.5, info.normal(), false);
        return;
    }
    marks_walked_ = k + 1;
    if (marks_[k].found) return;
    marks_[k].found = true;
    found_[k] = {(info.start() + info.end()) * 0.5, info.normal(), false};
}

void ContactEvents::sensed(const RigidShape& a, const RigidShape& b, const CollisionInfo& info) {
    if (a.isSensor() && b.isSensor()) return;
    if (kept()) report(a, b, (info.start() + info.end()) * 0.5, info.normal(), true);
}

void ContactEvents::crossed(const RigidShape& mover, const RigidShape& sensor, Vec2 point, Vec2 direction) {
    if (!kept()) return;
    // Named smaller id first, the normal from it to the other: along the motion when
    // the mover is the first of the pair, against it otherwise.
    const bool mover_first = mover.id() < sensor.id();
    const Vec2 normal = mover_first ? direction : direction * -1.0;
    report(mover_first ? mover : sensor, mover_first ? sensor : mover, point, normal, true);
}

ContactEvent ContactEvents::eventOf(EventKind kind, PairIds pair, const Sighting& seen, double speed) const {
    return {.step = step_,
            .kind = kind,
            .id_a = pair.first,
            .id_b = pair.second,
            .point = seen.point,
            .normal = seen.normal,
            .speed = speed};
}

void ContactEvents::endStep(ShapeList shapes, double hit_speed) {
    if (!kept()) return;
    closeRun();
    // A shape removed at the end of the step (out of bounds) touches nothing. Shapes
    // join the list at its end with ever larger ids: a list as long as at the last
    // step's end, ending in the same id, is the same list, and no shape has left it
    // (nor its ids_ changed) since.
    const bool same_shapes = shapes.size() == ids_.size() && (shapes.empty() || shapes.back()->id() == ids_.back());
    if (!same_shapes) {
        ids_.clear();
        for (const auto& shape : shapes) ids_.push_back(shape->id());
    }
    const auto there = [&](PairIds pair) {
        return same_shapes || (shapeWithId(shapes, ids_, pair.first) && shapeWithId(shapes, ids_, pair.second));
    };
    // The pairs touching before and the step's new ones, both sorted, merged into the
    // new list of pairs touching; the events come out in the order of their pairs.
    next_marks_.clear();
    next_touches_.clear();
    const auto goesOn = [&](PairIds pair, const Sighting& seen, int missed) {
        next_marks_.push_back({pair});
        next_touches_.push_back({seen, missed});
    };
    std::size_t k = 0;
    auto begun = begun_.begin();
    while (k < marks_.size() || begun != begun_.end()) {
        if (k == marks_.size() || (begun != begun_.end() && begun->pair < marks_[k].pair)) {
            if (there(begun->pair)) {
                events_.push_back(eventOf(EventKind::begin, begun->pair, begun->seen));
                if (!begun->seen.sensor && begun->speed > hit_speed) {
                    events_.push_back(eventOf(EventKind::hit, begun->pair, begun->seen, begun->speed));
                }
                goesOn(begun->pair, begun->seen, 0);
            }
            ++begun;
            continue;
        }
        const PairIds pair = marks_[k].pair;
        const Touch& before = touches_[k];
        if (marks_[k].found && there(pair)) {
            goesOn(pair, found_[k], 0);  // touching still: where it touches now
        } else {
            // Not found this step: still touching if both its shapes rest, since then no
            // pass tested it, or if the step before found it; otherwise it has ended.
            const RigidShape* a = shapeWithId(shapes, ids_, pair.first);
            const RigidShape* b = shapeWithId(shapes, ids_, pair.second);
            if (a && b && a->isResting() && b->isResting()) {
                goesOn(pair, before.seen, 0);  // asleep it is not missed, it is not looked for
            } else if (a && b && before.missed + 1 < kMissedSteps) {
                goesOn(pair, before.seen, before.missed + 1);
            } else {
                events_.push_back(eventOf(EventKind::end, pair, before.seen));
            }
        }
        ++k;
    }
    marks_.swap(next_marks_);
    touches_.swap(next_touches_);
    found_.resize(marks_.size());  // what it holds is read only where a report has written it
    begun_.clear();
    if (taking_in_) {
        // The first step heard: what touches was touching already (nothing could end).
        events_.clear();
        taking_in_ = false;
    }
    while (!recent_.empty() && recent_.front().step <= step_ - kShownSteps) recent_.pop_front();
    recent_.insert(recent_.end(), events_.begin(), events_.end());
}

void ContactEvents::limitReached(BodyId a, BodyId b, Vec2 point, Vec2 normal, double speed) {
    if (!kept()) return;
    // Named as a pair is, smaller id first, the normal still pointing from a to b.
    if (b < a) {
        std::swap(a, b);
        normal = normal * -1.0;
    }
    events_.push_back({.step = step_,
                       .kind = EventKind::limit,
                       .id_a = a,
                       .id_b = b,
                       .point = point,
                       .normal = normal,
                       .speed = speed});
}

void ContactEvents::shapeLeaves(BodyId id) {
    if (!kept()) return;
    std::size_t kept_pairs = 0;
    for (std::size_t k = 0; k < marks_.size(); ++k) {
        const PairIds pair = marks_[k].pair;
        if (pair.first == id || pair.second == id) {
            pending_.push_back(eventOf(EventKind::end, pair, touches_[k].seen));
        } else {
            marks_[kept_pairs] = marks_[k];
            touches_[kept_pairs] = touches_[k];
            ++kept_pairs;
        }
    }
    marks_.resize(kept_pairs);
    touches_.resize(kept_pairs);
    found_.resize(kept_pairs);
}

}  // namespace engine
