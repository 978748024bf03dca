// Bullet's continuous collision detection, with and without the certified pass
// of motion-bound (through its C ABI), in four stress worlds, judged by an
// independent checker. Built and run by ../bullet.sh.
//
// Each world is launched N times (argument 1, default 40; each launch a seed:
// random start poses, velocities and spins) and stepped 150 times at
// dt = 1/60 with gravity off (on in stack), twice with the same launches (argument 2, a
// world's name, runs that world alone):
//
// - bullet: Bullet's own CCD on every dynamic body (setCcdMotionThreshold,
//   setCcdSweptSphereRadius: a sphere swept along the translation);
// - ours: the same, and after each step the certified pass: each dynamic
//   body's actual motion over the step (its pose before and after
//   stepSimulation, as a constant-velocity motion by value:
//   mb_motion_value_between) cast against every other body with
//   mb_time_of_impact_values, unless certified apart
//   first (the segments its origin and the other's sweep, grown by their
//   reaches: apart wherever either stops; a fixed body by its box), and the
//   bodies moved back to their poses on those motions at the earliest time
//   of impact of their group (the dynamic bodies of the pairs examined stop
//   together). A pair within the contact distance at the start (a body
//   stopped there by the last step, or resting on the other) asks
//   mb_past_contact_below_values along the report's normal (proofs/12-shapes.md,
//   Lemma 12.14): its overlap along that normal may reach a ceiling (the
//   start's plus the contact distance, or the floor, the checker's
//   tolerance, when that is more), and the pair is stopped at the first
//   time it may pass it. The pass carries each touching pair's normal and
//   ceiling to the next step and asks that first: a resting or sliding pair
//   is decided by the closed form (no cast), a held pair keeps its ceiling,
//   and no ceiling rises above the one carried, so nothing creeps in. Only
//   when the rule cannot decide (both bodies turning fast) is the pair asked
//   again with a contact distance half its gap, and touching exactly held
//   at the start if the step leaves it deeper. The pass's time is counted
//   in the step's. Set BULLET_WORLDS_DEBUG=1 to print every cast and every
//   tunnelled or late step; BULLET_WORLDS_NO_CHECK=1 skips the checker (for
//   instruction counts; then a third argument, bullet or ours, runs one
//   setup).
//
// Worlds: board (a thin board flying and spinning fast at a thin wall), bat
// (a long thin capsule spinning in place beside a thin wall: pure rotation),
// bullets (two small balls head-on at 15 to 60 m/s each), plate (a cube,
// for motion-bound a triangle mesh, falling at 20 to 150 m/s and spinning
// onto a triangle-mesh plate of zero thickness), stack (four columns of five
// cubes resting on a floor under gravity, placed 1e-3 apart).
//
// The checker does not use the certified cast: for each step and each pair
// (a dynamic body and any other), the recorded poses before and after the
// step are interpolated (centre lerped, rotation slerped: the motion the pass
// casts), sampled densely (at least 64 samples, and enough that no point of
// either body moves more than TOL / 2 between samples), and at each sample the
// penetration depth is Bullet's static contactPairTest. With TOL = 0.01:
// tunnelled = the centre crosses a thin obstacle's mid-plane within its
// extent (or two balls pass each other), or start and end penetrate by at
// most TOL while a sample between penetrates by more; late = not tunnelled
// and the end pose penetrates by more than TOL. A world's line counts the
// launches with at least one such step.
#include <btBulletCollisionCommon.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <utility>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include "motion_bound.h"
}

namespace {

constexpr double DT = 1.0 / 60.0;
constexpr int STEPS = 150;
constexpr double TOL = 0.01;
// The environment read once (getenv scans it: per pair it cost the pass
// about as much as a closed-form check).
const bool DEBUG = std::getenv("BULLET_WORLDS_DEBUG") != nullptr;
const bool NO_CHECK = std::getenv("BULLET_WORLDS_NO_CHECK") != nullptr;

void check(mb_status s, const char *what) {
    if (s != MB_STATUS_OK) {
        std::fprintf(stderr, "motion_bound: %s: %s\n", what, mb_last_error_message());
        std::exit(2);
    }
}

struct Rng {
    unsigned long long s;
    explicit Rng(unsigned long long seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
    double next() {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        return double(s >> 11) / double(1ull << 53);
    }
    double in(double a, double b) { return a + (b - a) * next(); }
    btVector3 unit() {
        for (;;) {
            btVector3 v(in(-1, 1), in(-1, 1), in(-1, 1));
            double l = v.length();
            if (l > 0.1 && l <= 1) return v / l;
        }
    }
};

// A body in both libraries: Bullet's shape and object, motion-bound's shape.
struct Body {
    btCollisionShape *shape = nullptr;
    btRigidBody *rb = nullptr;
    mb_shape *ours = nullptr;
    bool dynamic = false;
    double reach = 0;          // bound of |point - centre| over the body
    int thin_axis = -1;        // a thin fixed obstacle: its thin axis
    double extent[3] = {0, 0, 0};  // and its half extents (for crossings)
    double ball_radius = 0;    // a ball (for the bullets world's crossings)
};

mb_pose to_pose(const btTransform &t) {
    btVector3 p = t.getOrigin();
    btQuaternion q = t.getRotation();
    mb_pose pose = {{p.x(), p.y(), p.z()}, {q.w(), q.x(), q.y(), q.z()}};
    return pose;
}

// The pose at fraction f of the way from a to b: the centre lerped, the
// rotation slerped along the shortest arc (mb_motion_between's motion).
btTransform between(const btTransform &a, const btTransform &b, double f) {
    btQuaternion qa = a.getRotation(), qb = b.getRotation();
    if (qa.dot(qb) < 0) qb = -qb;
    btQuaternion q = qa.slerp(qb, btScalar(f));
    btVector3 p = a.getOrigin().lerp(b.getOrigin(), btScalar(f));
    return btTransform(q, p);
}

struct Deepest : btCollisionWorld::ContactResultCallback {
    double depth = 0;
    btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *, int, int,
                             const btCollisionObjectWrapper *, int, int) override {
        depth = std::max(depth, -double(cp.getDistance()));
        return 0;
    }
};

struct World {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher{&config};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
    std::vector<Body> bodies;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btTriangleMesh>> meshes;
    std::vector<std::unique_ptr<btDefaultMotionState>> states;
    std::vector<std::unique_ptr<btRigidBody>> rbs;
    // The checker's objects (plain shapes at sampled poses).
    std::vector<std::unique_ptr<btCollisionObject>> probes;
    // The pass's pairs touching at the last step's start: the normal their
    // overlap is taken along and its ceiling (mb_past_contact_below).
    struct Touching {
        mb_vec3 normal;
        mb_ceiling ceiling;
    };
    std::map<std::pair<size_t, size_t>, Touching> touching;
    // The pass's scratch kept between steps: each body's origin segment's
    // box (lows, then highs).
    std::vector<std::array<double, 6>> span;

    World() { world.setGravity(btVector3(0, 0, 0)); }
    ~World() {
        for (auto &rb : rbs) world.removeRigidBody(rb.get());
        for (auto &b : bodies) mb_shape_free(b.ours);
    }

    Body &add(btCollisionShape *shape, mb_shape *ours, double mass, const btTransform &at,
              const btVector3 &v, const btVector3 &w, double reach, double swept_radius) {
        shapes.emplace_back(shape);
        btVector3 inertia(0, 0, 0);
        if (mass > 0) shape->calculateLocalInertia(btScalar(mass), inertia);
        states.emplace_back(new btDefaultMotionState(at));
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), states.back().get(), shape,
                                                      inertia);
        rbs.emplace_back(new btRigidBody(info));
        btRigidBody *rb = rbs.back().get();
        rb->setActivationState(DISABLE_DEACTIVATION);
        if (mass > 0) {
            rb->setLinearVelocity(v);
            rb->setAngularVelocity(w);
            rb->setCcdMotionThreshold(btScalar(1e-4));
            rb->setCcdSweptSphereRadius(btScalar(swept_radius));
            rb->setDamping(0, 0);
        }
        world.addRigidBody(rb);
        probes.emplace_back(new btCollisionObject());
        probes.back()->setCollisionShape(shape);
        Body b;
        b.shape = shape;
        b.rb = rb;
        b.ours = ours;
        b.dynamic = mass > 0;
        b.reach = reach;
        bodies.push_back(b);
        return bodies.back();
    }

    double depth(size_t i, const btTransform &ti, size_t j, const btTransform &tj) {
        probes[i]->setWorldTransform(ti);
        probes[j]->setWorldTransform(tj);
        Deepest d;
        world.contactPairTest(probes[i].get(), probes[j].get(), d);
        return d.depth;
    }
};

mb_shape *ours_box(double x, double y, double z) {
    mb_shape *s = nullptr;
    check(mb_shape_cuboid({x, y, z}, &s), "cuboid");
    return s;
}

// A static thin wall: the slab |x| <= 0.02, |y|, |z| <= 2.
void add_wall(World &w) {
    Body &b = w.add(new btBoxShape(btVector3(0.02f, 2, 2)), ours_box(0.02, 2, 2), 0,
                    btTransform::getIdentity(), btVector3(0, 0, 0), btVector3(0, 0, 0), 3, 0);
    b.thin_axis = 0;
    b.extent[0] = 0.02, b.extent[1] = 2, b.extent[2] = 2;
}

void build(World &w, const std::string &name, Rng &rng) {
    if (name == "board") {
        add_wall(w);
        btTransform at(btQuaternion(rng.unit(), btScalar(rng.in(0, 3))),
                       btVector3(btScalar(-rng.in(1.5, 2.5)), btScalar(rng.in(-0.5, 0.5)),
                                 btScalar(rng.in(-0.5, 0.5))));
        btVector3 v(btScalar(rng.in(8, 30)), 0, 0);
        btVector3 spin = rng.unit() * btScalar(rng.in(20, 80));
        w.add(new btBoxShape(btVector3(1.0f, 0.02f, 0.3f)), ours_box(1.0, 0.02, 0.3), 1, at, v,
              spin, std::sqrt(1.0 + 0.02 * 0.02 + 0.09), 0.018);
    } else if (name == "bat") {
        add_wall(w);
        // A bat of reach 0.84 about its centre, 0.55 to 0.78 from the wall,
        // spinning about z at 60 to 150 rad/s (1 to 2.5 rad a step) and
        // drifting slowly at it: its tip cuts the wall over an arc narrower
        // than a step's turn.
        btTransform at(btQuaternion(btVector3(0, 0, 1), btScalar(rng.in(0, 6.28))),
                       btVector3(btScalar(-rng.in(0.55, 0.78)), btScalar(rng.in(-0.5, 0.5)), 0));
        btVector3 v(btScalar(rng.in(0, 2)), 0, 0);
        btVector3 spin(0, 0, btScalar(rng.in(60, 150) * (rng.next() < 0.5 ? -1 : 1)));
        mb_shape *s = nullptr;
        check(mb_shape_capsule(0.8, 0.04, &s), "capsule");
        w.add(new btCapsuleShape(0.04f, 1.6f), s, 1, at, v, spin, 0.84, 0.036);
    } else if (name == "bullets") {
        double r = 0.05;
        for (int k = 0; k < 2; k++) {
            double sgn = k == 0 ? -1 : 1;
            btTransform at(btQuaternion::getIdentity(),
                           btVector3(btScalar(sgn * rng.in(1.5, 2.5)), btScalar(rng.in(-0.03, 0.03)),
                                     btScalar(rng.in(-0.03, 0.03))));
            btVector3 v(btScalar(-sgn * rng.in(15, 60)), 0, 0);
            mb_shape *s = nullptr;
            check(mb_shape_ball(r, &s), "ball");
            Body &b = w.add(new btSphereShape(btScalar(r)), s, 1, at, v, btVector3(0, 0, 0), r,
                            0.9 * r);
            b.ball_radius = r;
        }
    } else if (name == "stack") {
        // Four columns of five cubes (half side 0.1) resting on a fixed
        // floor under gravity, placed 1e-3 apart and jittered.
        w.world.setGravity(btVector3(0, 0, btScalar(-9.81)));
        w.add(new btBoxShape(btVector3(4, 4, 0.1f)), ours_box(4, 4, 0.1),
              0, btTransform(btQuaternion::getIdentity(), btVector3(0, 0, btScalar(-0.1))),
              btVector3(0, 0, 0), btVector3(0, 0, 0), 6, 0);
        const double h = 0.1;
        for (int col = 0; col < 4; col++) {
            for (int level = 0; level < 5; level++) {
                btVector3 at(btScalar((col % 2) * 0.6 - 0.3 + rng.in(-0.01, 0.01)),
                             btScalar((col / 2) * 0.6 - 0.3 + rng.in(-0.01, 0.01)),
                             btScalar(h + 1e-3 + level * (2 * h + 1e-3)));
                btQuaternion turn(btVector3(0, 0, 1), btScalar(rng.in(-0.1, 0.1)));
                w.add(new btBoxShape(btVector3(btScalar(h), btScalar(h), btScalar(h))),
                      ours_box(h, h, h), 1, btTransform(turn, at), btVector3(0, 0, 0),
                      btVector3(0, 0, 0), h * std::sqrt(3.0), 0.09);
            }
        }
    } else if (name == "plate") {
        // The plate [-5, 5]^2 in z = 0: two triangles, in both libraries.
        auto *tm = new btTriangleMesh();
        w.meshes.emplace_back(tm);
        tm->addTriangle(btVector3(-5, -5, 0), btVector3(5, -5, 0), btVector3(5, 5, 0));
        tm->addTriangle(btVector3(-5, -5, 0), btVector3(5, 5, 0), btVector3(-5, 5, 0));
        const double pv[12] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0};
        const uint32_t pt[6] = {0, 1, 2, 0, 2, 3};
        mb_shape *plate = nullptr;
        check(mb_shape_mesh(pv, 4, pt, 2, MB_MESH_SOLIDITY_HOLLOW, &plate), "plate");
        Body &b = w.add(new btBvhTriangleMeshShape(tm, true), plate, 0, btTransform::getIdentity(),
                        btVector3(0, 0, 0), btVector3(0, 0, 0), 8, 0);
        b.thin_axis = 2;
        b.extent[0] = 5, b.extent[1] = 5, b.extent[2] = 0;
        // A cube of half side 0.1: for motion-bound a closed triangle mesh.
        const double h = 0.1;
        double cv[24];
        const double corners[24] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                    -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
        for (int i = 0; i < 24; i++) cv[i] = corners[i] * h;
        const uint32_t ct[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                 2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
        mb_shape *cube = nullptr;
        check(mb_shape_mesh(cv, 8, ct, 12, MB_MESH_SOLIDITY_AUTO, &cube), "cube");
        btTransform at(btQuaternion(rng.unit(), btScalar(rng.in(0, 3))),
                       btVector3(btScalar(rng.in(-2, 2)), btScalar(rng.in(-2, 2)),
                                 btScalar(rng.in(1, 3))));
        btVector3 v(0, 0, btScalar(-rng.in(20, 150)));
        btVector3 spin = rng.unit() * btScalar(rng.in(0, 30));
        w.add(new btBoxShape(btVector3(btScalar(h), btScalar(h), btScalar(h))), cube, 1, at, v,
              spin, h * std::sqrt(3.0), 0.09);
    }
}

// The least distance between the segments [p0, p1] and [q0, q1] (Ericson,
// Real-Time Collision Detection, 5.1.9), in double.
double segment_distance(const btVector3 &p0, const btVector3 &p1, const btVector3 &q0,
                        const btVector3 &q1) {
    double d1[3], d2[3], r[3];
    for (int k = 0; k < 3; k++) {
        d1[k] = double(p1[k]) - double(p0[k]);
        d2[k] = double(q1[k]) - double(q0[k]);
        r[k] = double(p0[k]) - double(q0[k]);
    }
    auto dot = [](const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    double s = 0, t = 0;
    if (a <= 1e-300 && e <= 1e-300) {
        s = t = 0;
    } else if (a <= 1e-300) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        double c = dot(d1, r);
        if (e <= 1e-300) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            double b = dot(d1, d2), denom = a * e - b * b;
            s = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    double x = 0;
    for (int k = 0; k < 3; k++) {
        double d = r[k] + d1[k] * s - d2[k] * t;
        x += d * d;
    }
    return std::sqrt(x);
}

// The certified pass: every dynamic body moved back to its earliest time of
// impact along the motion it made over the step.
// Returns how many bodies it held (nearly) at their start pose.
int certified_pass(World &w, const std::vector<btTransform> &before, const mb_params &p) {
    // The overlap a touching pair may always reach (Lemma 12.14's floor):
    // the checker's tolerance (Bullet's own stack settles 0.012 to 0.016
    // deep, so a smaller floor holds resting boxes step after step).
    const double floor = TOL;
    size_t n = w.bodies.size();
    std::vector<btTransform> after(n);
    // Each body's motion by value (mb_motion_value: no handle, nothing to
    // free); a fixed body's is its pose with no velocity.
    std::vector<mb_motion_value> motion(n);
    std::vector<double> stop(n, DT);
    for (size_t i = 0; i < n; i++) {
        after[i] = w.bodies[i].rb->getWorldTransform();
        if (w.bodies[i].dynamic) {
            check(mb_motion_value_between(to_pose(before[i]), to_pose(after[i]), DT, &motion[i]),
                  "motion");
        } else {
            mb_pose at = to_pose(before[i]);
            motion[i] = {at.translation, {0, 0, 0}, at.rotation, {0, 0, 0}, {0, 0, 0}, DT};
        }
    }
    std::map<std::pair<size_t, size_t>, World::Touching> touching_next;
    // Dynamic bodies of pairs examined (not apart by their segments) stop
    // together, at their group's earliest time: each pair's answer holds
    // along both motions up to it (a body stopped alone while the other
    // moved on would leave that pair uncertified).
    std::vector<size_t> group(n);
    for (size_t k = 0; k < n; k++) group[k] = k;
    auto root = [&](size_t k) {
        while (group[k] != k) k = group[k] = group[group[k]];
        return k;
    };
    auto link = [&](size_t a, size_t b) { group[root(a)] = root(b); };
    // Each body's origin segment's box (from Bullet's floats, exact in
    // double): the largest gap between two boxes along an axis is at most
    // the segments' least distance, so a pair whose boxes are farther apart
    // than the test below needs is apart without the closed form (each gap
    // is one rounded difference, far inside that test's margin).
    std::vector<std::array<double, 6>> &span = w.span;
    span.resize(n);
    for (size_t k = 0; k < n; k++)
        for (int a = 0; a < 3; a++) {
            double x = double(before[k].getOrigin()[a]), y = double(after[k].getOrigin()[a]);
            span[k][a] = std::min(x, y);
            span[k][3 + a] = std::max(x, y);
        }
    for (size_t i = 0; i < n; i++) {
        if (!w.bodies[i].dynamic) continue;
        for (size_t j = 0; j < n; j++) {
            if (j == i || (w.bodies[j].dynamic && j < i)) continue;
            // Certified apart without a cast, wherever either stops: each
            // body stays within its reach of its origin, which moves along a
            // segment over the step (mb_motion_between turns about it); the
            // segments' least distance in closed form (in double, from
            // Bullet's exact floats; the margin covers its roundings).
            if (w.bodies[j].dynamic) {
                double need = w.bodies[i].reach + w.bodies[j].reach + p.contact_distance;
                double gap = 0;
                for (int a = 0; a < 3; a++)
                    gap = std::max({gap, span[j][a] - span[i][3 + a], span[i][a] - span[j][3 + a]});
                if (gap > need * (1 + 1e-9) + 1e-9) continue;
                double least = segment_distance(before[i].getOrigin(), after[i].getOrigin(),
                                                before[j].getOrigin(), after[j].getOrigin());
                if (least > need * (1 + 1e-9) + 1e-9) continue;
                // Examined: the two stop together (below).
                link(i, j);
            }
            // A fixed body: its box (Bullet's, margin included) against the
            // box of the moving body's ball along its origin's segment.
            if (!w.bodies[j].dynamic) {
                btVector3 lo, hi;
                w.bodies[j].shape->getAabb(before[j], lo, hi);
                bool meets = true;
                double grow = w.bodies[i].reach + p.contact_distance + 1e-6;
                for (int k = 0; k < 3; k++) {
                    double a = double(before[i].getOrigin()[k]), b = double(after[i].getOrigin()[k]);
                    if (std::min(a, b) - grow > double(hi[k]) || std::max(a, b) + grow < double(lo[k]))
                        meets = false;
                }
                if (!meets) continue;
            }
            // Touching at the last step's start: first the rule along that
            // step's normal with the ceiling carried (a resting or sliding
            // pair is decided by its closed form, no cast).
            auto key = std::make_pair(i, j);
            auto carried = w.touching.find(key);
            const mb_ceiling *last = nullptr;
            mb_below_report carried_below;
            if (carried != w.touching.end()) {
                last = &carried->second.ceiling;
                mb_below_report &below = carried_below;
                check(mb_past_contact_below_values(w.bodies[i].ours, &motion[i], w.bodies[j].ours,
                                                   &motion[j], carried->second.normal, last, floor, &p,
                                            &below),
                      "past contact below");
                if (DEBUG)
                    std::fprintf(stderr,
                                 "carried (%zu, %zu): outcome %d time %g overlap %g ceiling %g "
                                 "held %u cast %u\n",
                                 i, j, int(below.outcome), below.time, below.overlap,
                                 below.ceiling.value, below.ceiling.held, below.cast);
                if (below.outcome == MB_PAST_OUTCOME_NEVER) {
                    touching_next[key] = {carried->second.normal, below.ceiling};
                    continue;
                }
            }
            mb_report r;
            check(mb_time_of_impact_values(w.bodies[i].ours, &motion[i], w.bodies[j].ours, &motion[j],
                                           &p, &r),
                  "time of impact");
            if (DEBUG)
                std::fprintf(stderr, "cast (%zu, %zu): outcome %d time %g distance %g normal (%g %g %g)\n",
                             i, j, int(r.outcome), r.time, r.distance, r.normal.x, r.normal.y,
                             r.normal.z);
            if (r.outcome == MB_OUTCOME_SEPARATED) continue;
            double t = r.time;
            // Touching at the start: the rule along the carried normal, or
            // for a pair apart (within the contact distance) along the
            // report's normal, the direction of its closest points. An
            // overlapping pair's report has no trustworthy normal: along a
            // direction it overlaps much more than its depth, a ceiling
            // means nothing; such a pair not carried goes to the depths
            // below.
            bool carried_here = carried != w.touching.end();
            bool apart_normal = r.outcome == MB_OUTCOME_INITIAL_CONTACT && r.distance > 0 &&
                                std::isfinite(r.normal.x);
            if (r.outcome == MB_OUTCOME_INITIAL_CONTACT && (carried_here || apart_normal)) {
                mb_vec3 normal = carried_here ? carried->second.normal : r.normal;
                mb_below_report below = carried_below;
                if (!carried_here)
                    check(mb_past_contact_below_values(w.bodies[i].ours, &motion[i],
                                                       w.bodies[j].ours, &motion[j], normal, last, floor, &p, &below),
                          "past contact below");
                if (DEBUG)
                    std::fprintf(stderr, "  past contact: outcome %d time %g\n",
                                 int(below.outcome), below.time);
                if (below.outcome != MB_PAST_OUTCOME_UNDECIDED)
                    touching_next[key] = {normal, below.ceiling};
                if (below.outcome == MB_PAST_OUTCOME_NEVER) continue;
                if (below.outcome == MB_PAST_OUTCOME_AT) {
                    stop[i] = std::min(stop[i], below.time);
                    if (w.bodies[j].dynamic) stop[j] = std::min(stop[j], below.time);
                    continue;
                }
            }
            if (r.outcome == MB_OUTCOME_INITIAL_CONTACT && r.distance > 0) {
                // Within the contact distance at the start but apart (a body
                // stopped there by the last step): ask again with a contact
                // distance below the gap, so that a corner that cuts in
                // and out within the step is still found.
                mb_params closer = p;
                closer.contact_distance = 0.5 * r.distance;
                check(mb_time_of_impact_values(w.bodies[i].ours, &motion[i], w.bodies[j].ours,
                                               &motion[j], &closer, &r),
                      "time of impact");
                if (r.outcome == MB_OUTCOME_SEPARATED) continue;
                t = r.time;
            }
            if (r.outcome == MB_OUTCOME_INITIAL_CONTACT) {
                // Touching at the start: hold it there only if the step
                // leaves the pair deeper.
                double d0 = w.depth(i, before[i], j, before[j]);
                double d1 = w.depth(i, after[i], j, after[j]);
                if (d1 <= d0 + 1e-6) continue;
                t = 0;
            }
            stop[i] = std::min(stop[i], t);
            if (w.bodies[j].dynamic) stop[j] = std::min(stop[j], t);
        }
    }
    w.touching.swap(touching_next);
    std::vector<double> first(n, DT);
    for (size_t k = 0; k < n; k++) first[root(k)] = std::min(first[root(k)], stop[k]);
    for (size_t k = 0; k < n; k++) stop[k] = first[root(k)];
    int held = 0;
    for (size_t i = 0; i < n; i++) {
        held += w.bodies[i].dynamic && stop[i] < 1e-3 * DT;
        if (w.bodies[i].dynamic && stop[i] < DT) {
            btTransform t = between(before[i], after[i], stop[i] / DT);
            w.bodies[i].rb->setWorldTransform(t);
            w.bodies[i].rb->setInterpolationWorldTransform(t);
            w.bodies[i].rb->getMotionState()->setWorldTransform(t);
        }
    }
    return held;
}

struct Verdict {
    bool tunnelled = false, late = false;
};

// The independent checker of one step (see the header comment).
Verdict judge(World &w, const std::vector<btTransform> &before, const std::vector<btTransform> &after) {
    Verdict v;
    size_t n = w.bodies.size();
    for (size_t i = 0; i < n; i++) {
        if (!w.bodies[i].dynamic) continue;
        for (size_t j = 0; j < n; j++) {
            if (j == i || (w.bodies[j].dynamic && j < i)) continue;
            const Body &o = w.bodies[j];
            bool crossed = false;
            btVector3 c0 = before[i].getOrigin(), c1 = after[i].getOrigin();
            if (o.thin_axis >= 0) {
                int a = o.thin_axis;
                double s0 = c0[a] - before[j].getOrigin()[a], s1 = c1[a] - before[j].getOrigin()[a];
                if (s0 * s1 < 0) {
                    double f = s0 / (s0 - s1);
                    btVector3 c = c0.lerp(c1, btScalar(f)) - before[j].getOrigin();
                    bool inside = true;
                    for (int k = 0; k < 3; k++)
                        if (k != a && std::fabs(c[k]) > o.extent[k]) inside = false;
                    crossed = inside;
                }
            } else if (o.ball_radius > 0 && w.bodies[i].ball_radius > 0) {
                btVector3 r0 = before[j].getOrigin() - c0, r1 = after[j].getOrigin() - c1;
                if (r0.x() * r1.x() < 0) {
                    double f = r0.x() / (r0.x() - r1.x());
                    btVector3 r = r0.lerp(r1, btScalar(f));
                    crossed = std::hypot(r.y(), r.z()) < o.ball_radius + w.bodies[i].ball_radius;
                }
            }
            double move = (c1 - c0).length() + (after[j].getOrigin() - before[j].getOrigin()).length();
            double turn_i = before[i].getRotation().angleShortestPath(after[i].getRotation());
            double turn_j = before[j].getRotation().angleShortestPath(after[j].getRotation());
            move += turn_i * w.bodies[i].reach + (o.dynamic ? turn_j * o.reach : 0);
            int samples = std::max(64, int(std::ceil(move / (TOL / 2))));
            double d_start = w.depth(i, before[i], j, before[j]);
            double d_end = w.depth(i, after[i], j, after[j]);
            double d_max = 0;
            if (!crossed && d_start <= TOL && d_end <= TOL) {
                for (int k = 1; k < samples && d_max <= TOL; k++) {
                    double f = double(k) / samples;
                    d_max = std::max(d_max, w.depth(i, between(before[i], after[i], f), j,
                                                    between(before[j], after[j], f)));
                }
            }
            if (crossed || (d_start <= TOL && d_end <= TOL && d_max > TOL)) {
                v.tunnelled = true;
                if (DEBUG)
                    std::fprintf(stderr,
                                 "tunnelled: pair (%zu, %zu) crossed %d depth start %g end %g max %g "
                                 "centre (%g %g %g) -> (%g %g %g)\n",
                                 i, j, int(crossed), d_start, d_end, d_max, c0.x(), c0.y(), c0.z(),
                                 c1.x(), c1.y(), c1.z());
            }
            else if (d_end > TOL) {
                v.late = true;
                if (DEBUG)
                    std::fprintf(stderr, "late: pair (%zu, %zu) depth start %g end %g\n", i, j,
                                 d_start, d_end);
            }
        }
    }
    return v;
}

struct Tally {
    int tunnelled = 0, late = 0;
    int held = 0;  // launches where the pass held a body at its start in the last step
    double step_seconds = 0;
    long steps = 0;
};

Tally run(const std::string &name, int launches, bool ours) {
    Tally t;
    mb_params p = mb_params_default();
    p.contact_distance = 1e-3;
    if (DEBUG)
        std::fprintf(stderr, "run %s, %s\n", name.c_str(), ours ? "ours" : "bullet");
    for (int launch = 0; launch < launches; launch++) {
        Rng rng(1000 * (unsigned long long)(launch + 1) + name.size());
        World w;
        build(w, name, rng);
        size_t n = w.bodies.size();
        std::vector<btTransform> before(n), after(n);
        bool tunnelled = false, late = false;
        int held_last = 0;
        for (int s = 0; s < STEPS; s++) {
            for (size_t i = 0; i < n; i++) before[i] = w.bodies[i].rb->getWorldTransform();
            auto t0 = std::chrono::steady_clock::now();
            w.world.stepSimulation(btScalar(DT), 0, btScalar(DT));
            if (ours) held_last = certified_pass(w, before, p);
            t.step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            t.steps++;
            for (size_t i = 0; i < n; i++) after[i] = w.bodies[i].rb->getWorldTransform();
            // BULLET_WORLDS_NO_CHECK=1: no checker (for instruction counts).
            if (NO_CHECK) continue;
            Verdict v = judge(w, before, after);
            if (v.tunnelled && ours && DEBUG)
                std::fprintf(stderr, "  %s launch %d step %d\n", name.c_str(), launch, s);
            tunnelled = tunnelled || v.tunnelled;
            late = late || v.late;
        }
        t.tunnelled += tunnelled;
        t.late += late;
        t.held += held_last > 0;
    }
    return t;
}

}  // namespace

int main(int argc, char **argv) {
    int launches = argc > 1 ? std::atoi(argv[1]) : 40;
    // An optional second argument runs one world, a third one setup
    // ("bullet" or "ours"; for profiling).
    const char *only = argc > 2 ? argv[2] : nullptr;
    const char *mode = argc > 3 ? argv[3] : nullptr;
    if (launches <= 0) {
        std::fprintf(stderr, "usage: bullet_worlds [launches > 0] [board|bat|bullets|plate|stack] [bullet|ours]\n");
        return 2;
    }
    std::printf("%d launches x %d steps per world, dt = 1/60, tolerance %.3g\n", launches, STEPS,
                TOL);
    for (const char *name : {"board", "bat", "bullets", "plate", "stack"}) {
        if (only && std::strcmp(only, name) != 0) continue;
        bool both = !mode;
        Tally b = both || std::strcmp(mode, "bullet") == 0 ? run(name, launches, false) : Tally();
        Tally o = both || std::strcmp(mode, "ours") == 0 ? run(name, launches, true) : Tally();
        std::printf(
            "world %s: tunnelled bullet %d ours %d, late bullet %d ours %d, ms per step bullet %.4f "
            "ours %.4f\n",
            name, b.tunnelled, o.tunnelled, b.late, o.late,
            1e3 * b.step_seconds / std::max(b.steps, 1L), 1e3 * o.step_seconds / std::max(o.steps, 1L));
        // A body the pass holds at its start pose step after step would also
        // count 0: how many launches end that way.
        std::printf("  (ours held a body at its start pose in the last step in %d of %d launches)\n",
                    o.held, launches);
        std::fflush(stdout);
    }
    return 0;
}
