/*
 * The C ABI's tests: every entry point of motion_bound.h, bad input included,
 * answers checked against closed forms (not against values the library
 * printed). Built and run under AddressSanitizer, UndefinedBehaviorSanitizer
 * and LeakSanitizer by ../run_c_tests.sh. Exit code 0 when every check
 * passes, 1 otherwise.
 */
#include "motion_bound.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;
static int checks = 0;

#define CHECK(cond, ...)                                                       \
    do {                                                                       \
        checks++;                                                              \
        if (!(cond)) {                                                         \
            failures++;                                                        \
            fprintf(stderr, "%s:%d: FAILED %s: ", __FILE__, __LINE__, #cond);  \
            fprintf(stderr, __VA_ARGS__);                                      \
            fprintf(stderr, " (last error: %s)\n", mb_last_error_message());   \
        }                                                                      \
    } while (0)

/* A call that must succeed. */
#define OK(call) CHECK((call) == MB_STATUS_OK, "%s", #call)
/* Failing calls whose message was checked. */
static int message_checks = 0;

/* A call that must fail with `status` and a message beginning with `text`:
 * the argument's name (with its index in an array, its field in a struct:
 * `parts[1]`, `start.rotation`, `queries[2].motion_b`), then what was wrong,
 * as the Python module words it. */
#define FAILS(call, status, text)                                              \
    do {                                                                       \
        mb_status s_ = (call);                                                 \
        CHECK(s_ == (status), "%s gave %d, expected %d", #call, (int)s_,      \
              (int)(status));                                                  \
        message_checks++;                                                      \
        CHECK(strncmp(mb_last_error_message(), (text), strlen(text)) == 0,     \
              "%s: the message does not begin with \"%s\"", #call, (text));    \
    } while (0)

static const mb_quat IDENTITY = {1.0, 0.0, 0.0, 0.0};
static const mb_vec3 ZERO = {0.0, 0.0, 0.0};

static mb_vec3 v3(double x, double y, double z) {
    mb_vec3 v = {x, y, z};
    return v;
}

static mb_pose at(double x, double y, double z) {
    mb_pose p = {{x, y, z}, {1.0, 0.0, 0.0, 0.0}};
    return p;
}

/* The motion of a body that starts at `p` with velocities `v`, `w`. */
static mb_motion *moving(mb_pose p, mb_vec3 v, mb_vec3 w, double duration) {
    mb_motion *m = NULL;
    OK(mb_motion_from_velocities(p, v, w, duration, &m));
    return m;
}

/*
 * A contact declared by distance at `r.time` with the exact time of touching
 * `t_touch` and the time `t_within` the exact distance fell to the contact
 * distance: the distance at the reported time is at most the contact
 * distance, and the time is never later than touching, so
 * t_within <= time <= t_touch.
 */
static void expect_contact(const char *what, mb_report r, double t_within,
                           double t_touch) {
    CHECK(r.outcome == MB_OUTCOME_CONTACT, "%s: outcome %d", what,
          (int)r.outcome);
    CHECK(r.criterion == MB_CRITERION_DISTANCE, "%s: criterion %d", what,
          (int)r.criterion);
    CHECK(r.time >= t_within - 1e-12 && r.time <= t_touch + 1e-12,
          "%s: time %.17g outside [%.17g, %.17g]", what, r.time, t_within,
          t_touch);
    CHECK(r.iterations >= 1, "%s: %u iterations", what, r.iterations);
}

/* A contact on a straight approach at `speed` from gap `gap`. */
static void expect_linear(const char *what, mb_report r, double gap,
                          double speed, double d) {
    expect_contact(what, r, (gap - d) / speed, gap / speed);
}

static mb_report toi(const mb_shape *a, const mb_motion *ma, const mb_shape *b,
                     const mb_motion *mb_, const mb_params *p) {
    mb_report r;
    memset(&r, 0, sizeof r);
    OK(mb_time_of_impact(a, ma, b, mb_, p, &r));
    return r;
}

/* The closed (outward-wound) cube [-h, h]^3 as 8 vertices, 12 triangles. */
static const double CUBE_V[24] = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                  -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
static const uint32_t CUBE_T[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7,
                                    0, 1, 5, 0, 5, 4, 2, 3, 7, 2, 7, 6,
                                    1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};

static mb_shape *cube_mesh(double h, uint32_t solidity) {
    double v[24];
    for (int i = 0; i < 24; i++) v[i] = CUBE_V[i] * h;
    mb_shape *s = NULL;
    OK(mb_shape_mesh(v, 8, CUBE_T, 12, solidity, &s));
    return s;
}

/* The plate [-5, 5]^2 in z = 0: two triangles facing +z. */
static mb_shape *plate_mesh(void) {
    const double v[12] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0};
    const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
    mb_shape *s = NULL;
    OK(mb_shape_mesh(v, 4, t, 2, MB_MESH_SOLIDITY_AUTO, &s));
    return s;
}

static void test_version_and_params(void) {
    CHECK(strcmp(mb_version(), "0.1.0") == 0, "version %s", mb_version());
    mb_params p = mb_params_default();
    CHECK(p.contact_distance == 1e-4 && p.time_tolerance == 1e-9 &&
              p.max_iterations == 100 && p.iterations_per_turn == 16 &&
              p.horizon_factor == 2.0 && p.one_sided == 1 &&
              p.bound == MB_BOUND_AUTO && p.witness == MB_WITNESS_SEARCH_CLOSEST &&
              p.work_budget_node_pairs == 50000 &&
              p.work_budget_triangle_pairs == 10000,
          "the documented defaults");
}

/*
 * Two balls of radius 0.5 approaching head-on, centres at -2 and 2 moving at
 * +1 and -1: the gap 3 closes at 2, touching at t = 1.5.
 */
static void test_balls_head_on(void) {
    mb_shape *ball = NULL;
    OK(mb_shape_ball(0.5, &ball));
    mb_motion *ma = moving(at(-2, 0, 0), v3(1, 0, 0), ZERO, 2.0);
    mb_motion *mb_ = moving(at(2, 0, 0), v3(-1, 0, 0), ZERO, 2.0);
    mb_params p = mb_params_default();
    for (int k = 0; k < 3; k++) {
        p.bound = (uint32_t)k; /* auto, NEVQ, EVQ: the same certified answer */
        mb_report r = toi(ball, ma, ball, mb_, &p);
        expect_linear("balls", r, 3.0, 2.0, p.contact_distance);
        /* Witnesses on the centre line, on each ball's surface. */
        CHECK(fabs(r.witness_a.x - (-1.5 + r.time)) < 1e-9 &&
                  fabs(r.witness_b.x - (1.5 - r.time)) < 1e-9 &&
                  fabs(r.witness_a.y) < 1e-12 && fabs(r.witness_b.z) < 1e-12,
              "witnesses (%g %g %g) (%g %g %g) at %g", r.witness_a.x,
              r.witness_a.y, r.witness_a.z, r.witness_b.x, r.witness_b.y,
              r.witness_b.z, r.time);
        CHECK(fabs(r.distance - (r.witness_b.x - r.witness_a.x)) < 1e-9 &&
                  r.distance <= p.contact_distance,
              "distance %g", r.distance);
        CHECK(r.normal.x > 1.0 - 1e-12, "normal (%g %g %g)", r.normal.x,
              r.normal.y, r.normal.z);
    }
    /* NULL params: the defaults. */
    expect_linear("balls, NULL params", toi(ball, ma, ball, mb_, NULL), 3.0, 2.0,
                  1e-4);
    /* Receding: separated, time NaN. */
    mb_motion *away = moving(at(2, 0, 0), v3(3, 0, 0), ZERO, 2.0);
    mb_report r = toi(ball, ma, ball, away, NULL);
    CHECK(r.outcome == MB_OUTCOME_SEPARATED && isnan(r.time) &&
              isnan(r.witness_a.x) && r.criterion == MB_CRITERION_NONE,
          "receding: outcome %d time %g", (int)r.outcome, r.time);
    /* Overlapping at the start: initial contact at time 0. */
    mb_motion *near = moving(at(-0.2, 0, 0), ZERO, ZERO, 2.0);
    mb_motion *near2 = moving(at(0.2, 0, 0), ZERO, ZERO, 2.0);
    r = toi(ball, near, ball, near2, NULL);
    CHECK(r.outcome == MB_OUTCOME_INITIAL_CONTACT && r.time == 0.0,
          "overlap: outcome %d time %g", (int)r.outcome, r.time);
    /* A larger contact distance: the contact comes earlier, still bracketed. */
    p = mb_params_default();
    p.contact_distance = 0.5;
    expect_linear("balls, d = 0.5", toi(ball, ma, ball, mb_, &p), 3.0, 2.0, 0.5);
    mb_motion_free(ma);
    mb_motion_free(mb_);
    mb_motion_free(away);
    mb_motion_free(near);
    mb_motion_free(near2);
    mb_shape_free(ball);
}

/* Convex shapes dropped onto a still ground: touching when the lowest point
 * reaches the plane. */
static void test_convex_on_ground(void) {
    mb_shape *ground_z = NULL, *ground_y = NULL;
    OK(mb_shape_half_space(v3(0, 0, 2.5), &ground_z)); /* any length */
    OK(mb_shape_half_space(v3(0, 1, 0), &ground_y));
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 2.0);
    const double d = 1e-4;

    /* A ball of 0.25 from z = 2 at 3 per second: 1.75 / 3. */
    mb_shape *ball = NULL;
    OK(mb_shape_ball(0.25, &ball));
    mb_motion *fall = moving(at(0, 0, 2), v3(0, 0, -3), ZERO, 2.0);
    mb_report r = toi(ball, fall, ground_z, still, NULL);
    expect_linear("ball on ground", r, 1.75, 3.0, d);
    CHECK(r.normal.z < -1.0 + 1e-9, "normal from the ball to the ground: %g",
          r.normal.z);
    /* The ground first: the same time, the normal turned. */
    r = toi(ground_z, still, ball, fall, NULL);
    expect_linear("ground, ball", r, 1.75, 3.0, d);
    CHECK(r.normal.z > 1.0 - 1e-9, "normal %g", r.normal.z);

    /* Along y from y = 2 at 1 per second onto y = 0. */
    mb_motion *fall_y = moving(at(0, 2, 0), v3(0, -1, 0), ZERO, 2.0);
    /* A spin about y (the axis of these shapes) does not change when they
     * touch the plane y = 0. */
    mb_motion *fall_y_spin = moving(at(0, 2, 0), v3(0, -1, 0), v3(0, 7, 0), 2.0);
    struct {
        const char *what;
        mb_status (*make2)(double, double, mb_shape **);
        double a, b, lowest;
        mb_shape_kind kind;
    } axial[] = {
        {"capsule", mb_shape_capsule, 0.5, 0.2, 0.7, MB_SHAPE_KIND_CAPSULE},
        {"cylinder", mb_shape_cylinder, 0.5, 0.3, 0.5, MB_SHAPE_KIND_CYLINDER},
        {"cone", mb_shape_cone, 0.5, 0.3, 0.5, MB_SHAPE_KIND_CONE},
    };
    for (size_t i = 0; i < sizeof axial / sizeof axial[0]; i++) {
        mb_shape *s = NULL, *rounded = NULL;
        OK(axial[i].make2(axial[i].a, axial[i].b, &s));
        mb_shape_kind k;
        OK(mb_shape_get_kind(s, &k));
        CHECK(k == axial[i].kind, "%s kind %d", axial[i].what, (int)k);
        expect_linear(axial[i].what, toi(s, fall_y, ground_y, still, NULL),
                      2.0 - axial[i].lowest, 1.0, d);
        expect_linear(axial[i].what, toi(s, fall_y_spin, ground_y, still, NULL),
                      2.0 - axial[i].lowest, 1.0, d);
        /* Rounded by 0.1: touching 0.1 earlier. */
        OK(mb_shape_rounded(s, 0.1, &rounded));
        OK(mb_shape_get_kind(rounded, &k));
        CHECK(k == axial[i].kind, "rounded %s kind %d", axial[i].what, (int)k);
        expect_linear(axial[i].what, toi(rounded, fall_y, ground_y, still, NULL),
                      2.0 - axial[i].lowest - 0.1, 1.0, d);
        mb_shape_free(s);
        mb_shape_free(rounded);
    }

    /* A cuboid, a convex hull of the same cube's corners, both rounded. */
    mb_shape *box = NULL, *hull = NULL, *rbox = NULL, *rhull = NULL;
    OK(mb_shape_cuboid(v3(0.5, 0.5, 0.5), &box));
    double pts[24];
    for (int i = 0; i < 24; i++) pts[i] = CUBE_V[i] * 0.5;
    OK(mb_shape_convex_hull(pts, 8, &hull));
    OK(mb_shape_rounded(box, 0.1, &rbox));
    OK(mb_shape_rounded(hull, 0.1, &rhull));
    mb_shape_kind k;
    OK(mb_shape_get_kind(hull, &k));
    CHECK(k == MB_SHAPE_KIND_CONVEX_HULL, "hull kind %d", (int)k);
    OK(mb_shape_get_kind(box, &k));
    CHECK(k == MB_SHAPE_KIND_CUBOID, "box kind %d", (int)k);
    mb_motion *fall_z = moving(at(0, 0, 2), v3(0, 0, -1), ZERO, 2.0);
    mb_motion *fall_z_spin = moving(at(0, 0, 2), v3(0, 0, -1), v3(0, 0, 9), 2.0);
    expect_linear("cuboid", toi(box, fall_z, ground_z, still, NULL), 1.5, 1.0, d);
    expect_linear("cuboid spinning about z", toi(box, fall_z_spin, ground_z, still, NULL),
                  1.5, 1.0, d);
    expect_linear("hull", toi(hull, fall_z, ground_z, still, NULL), 1.5, 1.0, d);
    expect_linear("hull spinning", toi(hull, fall_z_spin, ground_z, still, NULL), 1.5,
                  1.0, d);
    expect_linear("rounded cuboid", toi(rbox, fall_z, ground_z, still, NULL), 1.4, 1.0,
                  d);
    expect_linear("rounded hull", toi(rhull, fall_z, ground_z, still, NULL), 1.4, 1.0,
                  d);
    /* A box turned 45 degrees about x stands on an edge: its lowest point is
     * sqrt(2) / 2 below its centre. */
    double c = cos(M_PI / 8), s = sin(M_PI / 8);
    mb_pose tilted = {{0, 0, 2}, {c, s, 0, 0}};
    mb_motion *tilted_fall = moving(tilted, v3(0, 0, -1), ZERO, 2.0);
    expect_linear("tilted cuboid", toi(box, tilted_fall, ground_z, still, NULL),
                  2.0 - sqrt(0.5), 1.0, d);

    /* Two half-spaces: no stepper. A turning half-space: refused. */
    FAILS(mb_time_of_impact(ground_z, still, ground_y, still, NULL, &r),
          MB_STATUS_QUERY_ERROR,
          "shape_a, shape_b: no stepper takes this pair of shape kinds (two");
    FAILS(mb_time_of_impact(ground_z, fall_z_spin, box, still, NULL, &r),
          MB_STATUS_QUERY_ERROR,
          "motion_a, motion_b: a half-space may only translate (no start");

    mb_shape *shapes[] = {ground_z, ground_y, ball, box, hull, rbox, rhull};
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        OK(mb_shape_free(shapes[i]));
    mb_motion *motions[] = {still, fall, fall_y, fall_y_spin, fall_z, fall_z_spin,
                            tilted_fall};
    for (size_t i = 0; i < sizeof motions / sizeof motions[0]; i++)
        OK(mb_motion_free(motions[i]));
}

/*
 * A rod spinning in place (no translation at all: linear CCD misses it)
 * strikes a ball. The capsule (half height 1 along y, radius 0.05) turns
 * about z at w; a ball of radius 0.1 sits at (-0.5, 0, 0). At angle a the
 * rod's axis is (-sin a, cos a, 0), whose distance from the ball's centre is
 * 0.5 cos a (the foot 0.5 sin a is within the segment): the surfaces touch
 * when 0.5 cos a = 0.15, and are within d when 0.5 cos a = 0.15 + d.
 */
static void test_spinning_rod(void) {
    mb_shape *rod = NULL, *ball = NULL;
    OK(mb_shape_capsule(1.0, 0.05, &rod));
    OK(mb_shape_ball(0.1, &ball));
    const double w = 10.0, d = 1e-4;
    mb_motion *spin = moving(at(0, 0, 0), ZERO, v3(0, 0, w), 1.0);
    mb_motion *still = moving(at(-0.5, 0, 0), ZERO, ZERO, 1.0);
    mb_report r = toi(rod, spin, ball, still, NULL);
    expect_contact("spinning rod", r, acos(2 * (0.15 + d)) / w, acos(0.3) / w);
    /* The witness on the ball is on its surface, towards the rod. */
    double dx = r.witness_b.x + 0.5, dy = r.witness_b.y, dz = r.witness_b.z;
    CHECK(fabs(sqrt(dx * dx + dy * dy + dz * dz) - 0.1) < 1e-9,
          "witness on the ball at distance %g from its centre",
          sqrt(dx * dx + dy * dy + dz * dz));
    mb_shape_free(rod);
    mb_shape_free(ball);
    mb_motion_free(spin);
    mb_motion_free(still);
}

/* Meshes: a cuboid and a mesh cube on a plate mesh, a solid mesh holding a
 * ball, a hollow one not. */
static void test_meshes(void) {
    mb_shape *plate = plate_mesh(), *box = NULL;
    mb_shape *cube = cube_mesh(0.5, MB_MESH_SOLIDITY_AUTO);
    OK(mb_shape_cuboid(v3(0.5, 0.5, 0.5), &box));
    mb_shape_kind k;
    OK(mb_shape_get_kind(plate, &k));
    CHECK(k == MB_SHAPE_KIND_MESH, "plate kind %d", (int)k);
    const double d = 1e-4;
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 2.0);
    /* From z = 3 at 2 per second: the bottom face (z = 2.5) meets the plate
     * at 1.25, whatever the spin about z. */
    mb_motion *fall = moving(at(0, 0, 3), v3(0, 0, -2), ZERO, 2.0);
    mb_motion *fall_spin = moving(at(0, 0, 3), v3(0, 0, -2), v3(0, 0, 5), 2.0);
    expect_linear("cuboid on plate", toi(box, fall, plate, still, NULL), 2.5, 2.0, d);
    expect_linear("plate under cuboid", toi(plate, still, box, fall_spin, NULL), 2.5,
                  2.0, d);
    expect_linear("mesh cube on plate", toi(cube, fall, plate, still, NULL), 2.5, 2.0,
                  d);
    /* Spinning, two meshes need more than the default work budget: the query
     * stops undecided (work limit) at a safe time before the contact; with no
     * budget it decides. */
    mb_report w = toi(cube, fall_spin, plate, still, NULL);
    CHECK((w.outcome == MB_OUTCOME_WORK_LIMIT && w.time <= 1.25) ||
              w.outcome == MB_OUTCOME_CONTACT,
          "spinning mesh cube, default budget: %d at %g", (int)w.outcome, w.time);
    mb_params unlimited = mb_params_default();
    unlimited.work_budget_node_pairs = UINT64_MAX;
    unlimited.work_budget_triangle_pairs = UINT64_MAX;
    w = toi(cube, fall_spin, plate, still, &unlimited);
    expect_linear("spinning mesh cube on plate", w, 2.5, 2.0, d);
    CHECK(w.node_pairs > 0 && w.triangle_pairs > 0, "work counted: %llu %llu",
          (unsigned long long)w.node_pairs, (unsigned long long)w.triangle_pairs);
    /* Off the plate's edge (x = 7): never meets it. */
    mb_motion *beside = moving(at(7, 0, 3), v3(0, 0, -2), ZERO, 2.0);
    mb_report r = toi(box, beside, plate, still, NULL);
    CHECK(r.outcome == MB_OUTCOME_SEPARATED, "beside the plate: %d", (int)r.outcome);

    /* A small ball inside the cube: in contact with the solid cube, not with
     * a hollow one (it stays 0.4 from every face). */
    mb_shape *hollow = cube_mesh(0.5, MB_MESH_SOLIDITY_HOLLOW);
    mb_shape *solid = cube_mesh(0.5, MB_MESH_SOLIDITY_SOLID);
    mb_shape *pebble = NULL;
    OK(mb_shape_ball(0.1, &pebble));
    r = toi(pebble, still, solid, still, NULL);
    CHECK(r.outcome == MB_OUTCOME_INITIAL_CONTACT, "inside solid: %d", (int)r.outcome);
    r = toi(pebble, still, hollow, still, NULL);
    CHECK(r.outcome == MB_OUTCOME_SEPARATED, "inside hollow: %d", (int)r.outcome);
    r = toi(pebble, still, cube, still, NULL);
    CHECK(r.outcome == MB_OUTCOME_INITIAL_CONTACT, "inside auto (closed): %d",
          (int)r.outcome);

    /* Bad meshes. */
    const double v[12] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0};
    const uint32_t bad_t[6] = {0, 1, 2, 0, 2, 4}; /* vertex 4 of 4 */
    const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
    double nan_v[12];
    memcpy(nan_v, v, sizeof v);
    nan_v[4] = NAN;
    mb_shape *m = (mb_shape *)0x1;
    FAILS(mb_shape_mesh(v, 4, bad_t, 2, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_INVALID_MESH,
          "indices: triangle 1 names vertex 4, but the mesh has 4 vertices");
    CHECK(m == (mb_shape *)0x1, "out written on failure");
    FAILS(mb_shape_mesh(v, 0, t, 2, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_INVALID_SIZE,
          "vertex_count is 0 (no vertices)");
    FAILS(mb_shape_mesh(v, 4, t, 0, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_INVALID_SIZE,
          "triangle_count is 0 (no triangles)");
    FAILS(mb_shape_mesh(NULL, 4, t, 2, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_NULL_POINTER,
          "vertices is NULL");
    FAILS(mb_shape_mesh(v, 4, NULL, 2, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_NULL_POINTER,
          "indices is NULL");
    FAILS(mb_shape_mesh(nan_v, 4, t, 2, MB_MESH_SOLIDITY_AUTO, &m), MB_STATUS_INVALID_INPUT,
          "vertices: invalid mesh vertex: vertex 1 is not finite");
    FAILS(mb_shape_mesh(v, 4, t, 2, 7, &m), MB_STATUS_INVALID_INPUT,
          "solidity is 7: 0 (auto), 1 (solid) or 2 (hollow)");
    FAILS(mb_shape_mesh(v, 4, t, 2, MB_MESH_SOLIDITY_SOLID, &m), MB_STATUS_INVALID_MESH,
          "solidity: mesh is not closed, so it cannot be solid: 4 unpaired and 0");
    FAILS(mb_shape_mesh(v, 4, t, 2, MB_MESH_SOLIDITY_AUTO, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    FAILS(mb_shape_mesh(v, SIZE_MAX / 2, t, 2, MB_MESH_SOLIDITY_AUTO, &m),
          MB_STATUS_INVALID_SIZE,
          "vertex_count is ");
    CHECK(m == (mb_shape *)0x1, "out written on failure");
    /* Rounding a mesh: refused. */
    FAILS(mb_shape_rounded(plate, 0.1, &m), MB_STATUS_INVALID_INPUT,
          "shape is not convex: only convex shapes (primitives and hulls) can be");

    mb_shape *shapes[] = {plate, box, cube, hollow, solid, pebble};
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        OK(mb_shape_free(shapes[i]));
    mb_motion *motions[] = {still, fall, fall_spin, beside};
    for (size_t i = 0; i < sizeof motions / sizeof motions[0]; i++)
        OK(mb_motion_free(motions[i]));
}

/*
 * A compound: two balls of 0.3 at x = +-1, a bar (a capsule turned to lie
 * along x), and a mesh cube of half side 0.5 at z = -1 (turned a quarter
 * about z, which maps the cube onto itself). Falling at 1 from z = 2 onto
 * the ground z = 0, the cube's bottom (z = 0.5) touches first, at 0.5.
 */
static void test_compound(void) {
    mb_shape *ball = NULL, *bar = NULL, *cube = cube_mesh(0.5, MB_MESH_SOLIDITY_AUTO);
    mb_shape *ground = NULL, *compound = NULL, *balls_only = NULL;
    OK(mb_shape_ball(0.3, &ball));
    OK(mb_shape_capsule(1.0, 0.05, &bar));
    OK(mb_shape_half_space(v3(0, 0, 1), &ground));
    double h = sqrt(0.5);
    mb_pose quarter_z = {{0, 0, 0}, {h, 0, 0, h}};
    mb_pose cube_at = {{0, 0, -1}, {h, 0, 0, h}};
    mb_shape *parts[4] = {ball, ball, bar, cube};
    mb_pose poses[4] = {at(-1, 0, 0), at(1, 0, 0), quarter_z, cube_at};
    OK(mb_shape_compound(parts, poses, 4, &compound));
    OK(mb_shape_compound(parts, poses, 2, &balls_only));
    /* The parts are copied: freeing them leaves the compound whole. */
    OK(mb_shape_free(cube));
    OK(mb_shape_free(bar));
    mb_shape_kind k;
    OK(mb_shape_get_kind(compound, &k));
    CHECK(k == MB_SHAPE_KIND_COMPOUND, "compound kind %d", (int)k);
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 2.0);
    mb_motion *fall = moving(at(0, 0, 2), v3(0, 0, -1), ZERO, 2.0);
    expect_linear("compound", toi(compound, fall, ground, still, NULL), 0.5, 1.0, 1e-4);
    expect_linear("dumbbell", toi(balls_only, fall, ground, still, NULL), 1.7, 1.0,
                  1e-4);
    /* Compound against compound: the dumbbell falling at 2 onto another at
     * rest 3 below it, balls straight over balls: gap 3 - 0.6 = 2.4. */
    mb_motion *above = moving(at(0, 0, 3), v3(0, 0, -2), ZERO, 2.0);
    expect_linear("dumbbell on dumbbell", toi(balls_only, above, balls_only, still, NULL),
                  2.4, 2.0, 1e-4);

    /* Bad compounds. */
    mb_shape *m = NULL;
    FAILS(mb_shape_compound(parts, poses, 0, &m), MB_STATUS_INVALID_SIZE,
          "count is 0: a compound needs a part");
    FAILS(mb_shape_compound(NULL, poses, 2, &m), MB_STATUS_NULL_POINTER,
          "parts is NULL");
    FAILS(mb_shape_compound(parts, NULL, 2, &m), MB_STATUS_NULL_POINTER,
          "poses is NULL");
    mb_shape *with_ground[2] = {ball, ground};
    FAILS(mb_shape_compound(with_ground, poses, 2, &m), MB_STATUS_INVALID_INPUT,
          "parts[1] is a half_space: a compound's parts are meshes and convex");
    mb_shape *with_null[2] = {ball, NULL};
    FAILS(mb_shape_compound(with_null, poses, 2, &m), MB_STATUS_NULL_POINTER,
          "parts[1] is NULL");
    mb_shape *with_freed[2] = {ball, cube}; /* freed above */
    FAILS(mb_shape_compound(with_freed, poses, 2, &m), MB_STATUS_INVALID_HANDLE,
          "parts[1] is not a live shape: never made by this library, or freed");
    mb_pose bad_pose[2] = {at(0, 0, 0), {{0, 0, 0}, {0, 0, 0, 0}}};
    FAILS(mb_shape_compound(parts, bad_pose, 2, &m), MB_STATUS_INVALID_INPUT,
          "poses[1].rotation: quaternion has zero length");
    CHECK(m == NULL, "out written on failure");

    OK(mb_shape_free(ball));
    OK(mb_shape_free(ground));
    OK(mb_shape_free(compound));
    OK(mb_shape_free(balls_only));
    OK(mb_motion_free(still));
    OK(mb_motion_free(fall));
    OK(mb_motion_free(above));
}

/* Motions: between two poses, about a centre, and where points go. */
static void test_motions(void) {
    double h = sqrt(0.5);
    /* From the origin to (2, 0, 0) turned a quarter about z, over 0.5: the
     * body point (1, 0, 0) ends at (2, 1, 0). */
    mb_pose start = at(0, 0, 0), end = {{2, 0, 0}, {h, 0, 0, h}};
    mb_motion *m = NULL;
    OK(mb_motion_between(start, end, 0.5, &m));
    mb_vec3 p;
    OK(mb_motion_point_at(m, v3(1, 0, 0), 0.5, &p));
    CHECK(fabs(p.x - 2) < 1e-12 && fabs(p.y - 1) < 1e-12 && fabs(p.z) < 1e-12,
          "end point (%g %g %g)", p.x, p.y, p.z);
    OK(mb_motion_point_at(m, v3(0, 0, 0), 0.25, &p));
    CHECK(fabs(p.x - 1) < 1e-12 && fabs(p.y) < 1e-12, "origin halfway (%g %g)", p.x,
          p.y);
    OK(mb_motion_free(m));

    /* The same about the body point (1, 0, 0): it moves on the straight
     * line from (1, 0, 0) to (2, 1, 0); the body origin ends at (2, 0, 0). */
    OK(mb_motion_between_about(start, end, 0.5, v3(1, 0, 0), &m));
    OK(mb_motion_point_at(m, v3(1, 0, 0), 0.25, &p));
    CHECK(fabs(p.x - 1.5) < 1e-12 && fabs(p.y - 0.5) < 1e-12, "centre halfway (%g %g)",
          p.x, p.y);
    OK(mb_motion_point_at(m, v3(0, 0, 0), 0.5, &p));
    CHECK(fabs(p.x - 2) < 1e-12 && fabs(p.y) < 1e-12, "origin at the end (%g %g)", p.x,
          p.y);
    OK(mb_motion_free(m));

    /* Turning about its centre of mass (1, 0, 0) placed at the origin, a
     * quarter turn per unit time about z: the body origin starts at
     * (-1, 0, 0) and is at (0, -1, 0) at t = 1, while it drifts by (0, 0, t). */
    OK(mb_motion_about_centre(v3(0, 0, 0), v3(1, 0, 0), IDENTITY, v3(0, 0, 1),
                              v3(0, 0, M_PI / 2), 2.0, &m));
    OK(mb_motion_point_at(m, v3(0, 0, 0), 1.0, &p));
    CHECK(fabs(p.x) < 1e-12 && fabs(p.y + 1) < 1e-12 && fabs(p.z - 1) < 1e-12,
          "origin (%g %g %g)", p.x, p.y, p.z);
    OK(mb_motion_point_at(m, v3(1, 0, 0), 1.5, &p));
    CHECK(fabs(p.x) < 1e-12 && fabs(p.y) < 1e-12 && fabs(p.z - 1.5) < 1e-12,
          "centre (%g %g %g)", p.x, p.y, p.z);

    /* Bad motions. */
    mb_motion *bad = (mb_motion *)0x1;
    mb_pose zero_q = {{0, 0, 0}, {0, 0, 0, 0}};
    FAILS(mb_motion_from_velocities(zero_q, ZERO, ZERO, 1.0, &bad), MB_STATUS_INVALID_INPUT,
          "start.rotation: quaternion has zero length");
    FAILS(mb_motion_from_velocities(start, v3(NAN, 0, 0), ZERO, 1.0, &bad),
          MB_STATUS_INVALID_INPUT,
          "linear.x is not finite (got NaN)");
    FAILS(mb_motion_from_velocities(start, ZERO, v3(0, INFINITY, 0), 1.0, &bad),
          MB_STATUS_INVALID_INPUT,
          "angular.y is not finite (got inf)");
    FAILS(mb_motion_from_velocities(start, ZERO, ZERO, 0.0, &bad), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got 0)");
    FAILS(mb_motion_from_velocities(start, ZERO, ZERO, NAN, &bad), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got NaN)");
    FAILS(mb_motion_from_velocities(start, ZERO, ZERO, 1.0, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    FAILS(mb_motion_between(start, zero_q, 1.0, &bad), MB_STATUS_INVALID_INPUT,
          "end.rotation: quaternion has zero length");
    FAILS(mb_motion_between(start, end, -1.0, &bad), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got -1)");
    FAILS(mb_motion_between_about(start, end, 1.0, v3(NAN, 0, 0), &bad),
          MB_STATUS_INVALID_INPUT,
          "local_centre.x is not finite (got NaN)");
    FAILS(mb_motion_about_centre(v3(0, 0, NAN), ZERO, IDENTITY, ZERO, ZERO, 1.0, &bad),
          MB_STATUS_INVALID_INPUT,
          "centre.z is not finite (got NaN)");
    CHECK(bad == (mb_motion *)0x1, "out written on failure");
    FAILS(mb_motion_point_at(m, ZERO, NAN, &p), MB_STATUS_INVALID_INPUT,
          "t is not finite (got NaN)");
    FAILS(mb_motion_point_at(m, ZERO, 0.0, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    FAILS(mb_motion_point_at(NULL, ZERO, 0.0, &p), MB_STATUS_NULL_POINTER,
          "motion is NULL");
    OK(mb_motion_free(m));
}

/* Null, freed, mistyped and foreign handles; bad parameters; NaN sizes. */
static void test_bad_handles_and_params(void) {
    mb_shape *ball = NULL;
    OK(mb_shape_ball(0.5, &ball));
    mb_motion *m = moving(at(0, 0, 0), ZERO, ZERO, 1.0);
    mb_motion *other = moving(at(3, 0, 0), ZERO, ZERO, 2.0); /* another interval */
    mb_report r;
    memset(&r, 0x5a, sizeof r);
    mb_report before = r;

    FAILS(mb_time_of_impact(NULL, m, ball, m, NULL, &r), MB_STATUS_NULL_POINTER,
          "shape_a is NULL");
    FAILS(mb_time_of_impact(ball, NULL, ball, m, NULL, &r), MB_STATUS_NULL_POINTER,
          "motion_a is NULL");
    FAILS(mb_time_of_impact(ball, m, NULL, m, NULL, &r), MB_STATUS_NULL_POINTER,
          "shape_b is NULL");
    FAILS(mb_time_of_impact(ball, m, ball, NULL, NULL, &r), MB_STATUS_NULL_POINTER,
          "motion_b is NULL");
    FAILS(mb_time_of_impact(ball, m, ball, m, NULL, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    /* A motion passed as a shape, a shape as a motion: the registry knows. */
    FAILS(mb_time_of_impact((const mb_shape *)m, m, ball, m, NULL, &r),
          MB_STATUS_INVALID_HANDLE,
          "shape_a is a handle of another type (not a shape)");
    FAILS(mb_time_of_impact(ball, (const mb_motion *)ball, ball, m, NULL, &r),
          MB_STATUS_INVALID_HANDLE,
          "motion_a is a handle of another type (not a motion)");
    /* A pointer this library never gave out (never read). */
    double junk[16] = {0};
    FAILS(mb_time_of_impact((const mb_shape *)junk, m, ball, m, NULL, &r),
          MB_STATUS_INVALID_HANDLE,
          "shape_a is not a live shape: never made by this library, or freed");
    FAILS(mb_shape_free((mb_shape *)junk), MB_STATUS_INVALID_HANDLE,
          "shape is not a live shape: never made by this library, or freed");
    /* Motions over different intervals. */
    FAILS(mb_time_of_impact(ball, m, ball, other, NULL, &r), MB_STATUS_QUERY_ERROR,
          "motion_a, motion_b: the two motions have different intervals");
    /* Parameters out of range. */
    mb_params p = mb_params_default();
    p.contact_distance = 0.0;
    FAILS(mb_time_of_impact(ball, m, ball, other, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: contact_distance (positive and finite)");
    p = mb_params_default();
    p.contact_distance = NAN;
    FAILS(mb_time_of_impact(ball, m, ball, m, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: contact_distance (positive and finite)");
    p = mb_params_default();
    p.max_iterations = 0;
    FAILS(mb_time_of_impact(ball, m, ball, m, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: max_iterations (at least 1)");
    p = mb_params_default();
    p.horizon_factor = 0.5;
    FAILS(mb_time_of_impact(ball, m, ball, m, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: horizon_factor (0 or above 1)");
    p = mb_params_default();
    p.bound = 3;
    FAILS(mb_time_of_impact(ball, m, ball, m, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params.bound is 3: 0 (auto), 1 (NEVQ) or 2 (EVQ)");
    p = mb_params_default();
    p.witness = 2;
    FAILS(mb_time_of_impact(ball, m, ball, m, &p, &r), MB_STATUS_INVALID_PARAMETER,
          "params.witness is 2: 0 (closest) or 1 (first)");
    CHECK(memcmp(&r, &before, sizeof r) == 0, "the report was written on failure");

    /* Bad shapes. */
    mb_shape *s = NULL;
    FAILS(mb_shape_ball(NAN, &s), MB_STATUS_INVALID_INPUT,
          "radius is not finite (got NaN)");
    FAILS(mb_shape_ball(-1.0, &s), MB_STATUS_INVALID_INPUT,
          "radius is negative (got -1)");
    FAILS(mb_shape_ball(INFINITY, &s), MB_STATUS_INVALID_INPUT,
          "radius is not finite (got inf)");
    FAILS(mb_shape_ball(1.0, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    FAILS(mb_shape_capsule(NAN, 1.0, &s), MB_STATUS_INVALID_INPUT,
          "half_height is not finite (got NaN)");
    FAILS(mb_shape_cuboid(v3(1, NAN, 1), &s), MB_STATUS_INVALID_INPUT,
          "half_extents[1] is not finite (got NaN)");
    /* The example, word for word as Python says it. */
    FAILS(mb_shape_cuboid(v3(1, -2, 1), &s), MB_STATUS_INVALID_INPUT,
          "half_extents[1] is negative (got -2)");
    FAILS(mb_shape_capsule(1.0, -0.5, &s), MB_STATUS_INVALID_INPUT,
          "radius is negative (got -0.5)");
    mb_pose far = {{1e300, 0, 0}, {1, 0, 0, 0}};
    mb_motion *mm = NULL;
    FAILS(mb_motion_between(far, far, 1.0, &mm), MB_STATUS_INVALID_INPUT,
          "start: pose exceeds the largest supported magnitude");
    mb_pose inf_at = {{0, INFINITY, 0}, {1, 0, 0, 0}};
    FAILS(mb_motion_between(at(0, 0, 0), inf_at, 1.0, &mm), MB_STATUS_INVALID_INPUT,
          "end.translation.y is not finite (got inf)");
    FAILS(mb_shape_cylinder(0.0, 1.0, &s), MB_STATUS_INVALID_INPUT,
          "half_height must be positive and finite (got 0)");
    FAILS(mb_shape_cone(1.0, -1.0, &s), MB_STATUS_INVALID_INPUT,
          "radius is negative (got -1)");
    FAILS(mb_shape_half_space(ZERO, &s), MB_STATUS_INVALID_INPUT,
          "normal: direction has zero length");
    FAILS(mb_shape_half_space(v3(0, 0, NAN), &s), MB_STATUS_INVALID_INPUT,
          "normal: direction is not finite");
    const double pts[6] = {0, 0, 0, 1, NAN, 0};
    FAILS(mb_shape_convex_hull(pts, 2, &s), MB_STATUS_INVALID_INPUT,
          "points: vertex 1 is not finite");
    FAILS(mb_shape_convex_hull(pts, 0, &s), MB_STATUS_INVALID_SIZE,
          "point_count is 0 (no points)");
    FAILS(mb_shape_convex_hull(NULL, 2, &s), MB_STATUS_NULL_POINTER,
          "points is NULL");
    FAILS(mb_shape_rounded(ball, NAN, &s), MB_STATUS_INVALID_INPUT,
          "radius is not finite (got NaN)");
    FAILS(mb_shape_rounded(ball, -0.1, &s), MB_STATUS_INVALID_INPUT,
          "radius is negative (got -0.1)");
    FAILS(mb_shape_rounded(NULL, 0.1, &s), MB_STATUS_NULL_POINTER,
          "shape is NULL");
    FAILS(mb_shape_get_kind(NULL, NULL), MB_STATUS_NULL_POINTER,
          "shape is NULL");
    FAILS(mb_shape_get_kind(ball, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    CHECK(s == NULL, "out written on failure");

    /* A message names the problem. */
    mb_shape_ball(-1.0, &s);
    CHECK(strstr(mb_last_error_message(), "radius") != NULL, "message: %s",
          mb_last_error_message());

    /* Freeing: NULL is fine; a second free is refused, not a double free;
     * a freed handle is refused, not read. */
    OK(mb_shape_free(NULL));
    OK(mb_motion_free(NULL));
    OK(mb_scene_free(NULL));
    OK(mb_scene_result_free(NULL));
    FAILS(mb_motion_free((mb_motion *)ball), MB_STATUS_INVALID_HANDLE,
          "motion is a handle of another type (not a motion)");
    OK(mb_shape_free(ball));
    FAILS(mb_shape_free(ball), MB_STATUS_INVALID_HANDLE,
          "shape is not a live shape: never made by this library, or freed");
    mb_shape_kind k;
    FAILS(mb_shape_get_kind(ball, &k), MB_STATUS_INVALID_HANDLE,
          "shape is not a live shape: never made by this library, or freed");
    OK(mb_motion_free(m));
    FAILS(mb_motion_point_at(m, ZERO, 0.0, &(mb_vec3){0}), MB_STATUS_INVALID_HANDLE,
          "motion is not a live motion: never made by this library, or freed");
    FAILS(mb_motion_free(m), MB_STATUS_INVALID_HANDLE,
          "motion is not a live motion: never made by this library, or freed");
    OK(mb_motion_free(other));
}

/*
 * A scene over [0, 1]: the ground, a ball of 0.5 falling from z = 2 at 3
 * (touching at 0.5), a ball far away falling at 1 (reaches the ground at
 * 1.5, after the frame), and a spinning rod beside a ball (as in
 * test_spinning_rod, shifted to x = 20).
 */
static void test_scene(void) {
    mb_scene *scene = NULL;
    OK(mb_scene_new(1.0, &scene));
    mb_shape *ground = NULL, *ball = NULL, *rod = NULL, *small = NULL;
    OK(mb_shape_half_space(v3(0, 0, 1), &ground));
    OK(mb_shape_ball(0.5, &ball));
    OK(mb_shape_capsule(1.0, 0.05, &rod));
    OK(mb_shape_ball(0.1, &small));
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 1.0);
    mb_motion *fall = moving(at(0, 0, 2), v3(0, 0, -3), ZERO, 1.0);
    mb_motion *slow = moving(at(10, 0, 2), v3(0, 0, -1), ZERO, 1.0);
    mb_motion *spin = moving(at(20, 0, 5), ZERO, v3(0, 0, 10), 1.0);
    mb_motion *beside = moving(at(19.5, 0, 5), ZERO, ZERO, 1.0);
    size_t idx[5];
    OK(mb_scene_add(scene, ground, still, &idx[0]));
    OK(mb_scene_add(scene, ball, fall, &idx[1]));
    OK(mb_scene_add(scene, ball, slow, &idx[2]));
    OK(mb_scene_add(scene, rod, spin, &idx[3]));
    OK(mb_scene_add(scene, small, beside, NULL)); /* NULL index: fine */
    idx[4] = 4;
    for (size_t i = 0; i < 5; i++) CHECK(idx[i] == i, "body %zu numbered %zu", i, idx[i]);
    size_t n = 0;
    OK(mb_scene_len(scene, &n));
    CHECK(n == 5, "scene of %zu bodies", n);
    /* The scene shares its shapes: they may be freed now. */
    OK(mb_shape_free(ball));
    OK(mb_shape_free(rod));

    mb_scene_result *result = NULL;
    OK(mb_scene_query(scene, NULL, &result));
    size_t count = 0;
    OK(mb_scene_result_len(result, &count));
    int seen_fall = 0, seen_rod = 0;
    for (size_t k = 0; k < count; k++) {
        mb_scene_pair pair;
        OK(mb_scene_result_get(result, k, &pair));
        CHECK(pair.a < pair.b && pair.b < 5, "pair (%zu, %zu)", pair.a, pair.b);
        if (pair.a == 0 && pair.b == 1) {
            seen_fall = 1;
            expect_linear("scene: ball on ground", pair.report, 1.5, 3.0, 1e-4);
        } else if (pair.a == 3 && pair.b == 4) {
            seen_rod = 1;
            expect_contact("scene: spinning rod", pair.report,
                           acos(2 * (0.15 + 1e-4)) / 10.0, acos(0.3) / 10.0);
        } else {
            CHECK(pair.report.outcome == MB_OUTCOME_SEPARATED,
                  "pair (%zu, %zu): outcome %d", pair.a, pair.b,
                  (int)pair.report.outcome);
        }
    }
    CHECK(seen_fall && seen_rod, "the two contacts listed (%d, %d) among %zu pairs",
          seen_fall, seen_rod, count);
    mb_scene_pair pair;
    FAILS(mb_scene_result_get(result, count, &pair), MB_STATUS_OUT_OF_RANGE,
          "index 2 is past the end of a result of 2 pairs");
    FAILS(mb_scene_result_get(result, 0, NULL), count > 0 ? MB_STATUS_NULL_POINTER
                                                          : MB_STATUS_OUT_OF_RANGE,
          "out is NULL");
    /* Parameters out of range. */
    mb_params p = mb_params_default();
    p.contact_distance = -1.0;
    mb_scene_result *bad = NULL;
    FAILS(mb_scene_query(scene, &p, &bad), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: contact_distance (positive and finite)");
    FAILS(mb_scene_query(scene, NULL, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    CHECK(bad == NULL, "out written on failure");

    /* A motion over another interval; bad scenes. */
    mb_motion *longer = moving(at(0, 0, 0), ZERO, ZERO, 2.0);
    FAILS(mb_scene_add(scene, ground, longer, NULL), MB_STATUS_QUERY_ERROR,
          "motion is over [0, 2], the scene over [0, 1]");
    FAILS(mb_scene_add(NULL, ground, still, NULL), MB_STATUS_NULL_POINTER,
          "scene is NULL");
    FAILS(mb_scene_add(scene, NULL, still, NULL), MB_STATUS_NULL_POINTER,
          "shape is NULL");
    FAILS(mb_scene_add(scene, ground, NULL, NULL), MB_STATUS_NULL_POINTER,
          "motion is NULL");
    FAILS(mb_scene_add((mb_scene *)result, ground, still, NULL), MB_STATUS_INVALID_HANDLE,
          "scene is a handle of another type (not a scene)");
    FAILS(mb_scene_len(NULL, &n), MB_STATUS_NULL_POINTER,
          "scene is NULL");
    FAILS(mb_scene_result_len(NULL, &count), MB_STATUS_NULL_POINTER,
          "result is NULL");
    FAILS(mb_scene_result_len((mb_scene_result *)scene, &count), MB_STATUS_INVALID_HANDLE,
          "result is a handle of another type (not a scene result)");
    mb_scene *s2 = NULL;
    FAILS(mb_scene_new(0.0, &s2), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got 0)");
    FAILS(mb_scene_new(NAN, &s2), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got NaN)");
    FAILS(mb_scene_new(1.0, NULL), MB_STATUS_NULL_POINTER,
          "out is NULL");
    /* Two half-spaces in a scene: the pair is skipped, not an error. */
    OK(mb_scene_new(1.0, &s2));
    OK(mb_scene_add(s2, ground, still, NULL));
    OK(mb_scene_add(s2, ground, still, NULL));
    mb_scene_result *r2 = NULL;
    OK(mb_scene_query(s2, NULL, &r2));
    OK(mb_scene_result_len(r2, &count));
    CHECK(count == 0, "two half-spaces: %zu pairs", count);

    /* The scene freed first: its result stays valid. */
    OK(mb_scene_free(scene));
    OK(mb_scene_result_len(result, &count));
    FAILS(mb_scene_free(scene), MB_STATUS_INVALID_HANDLE,
          "scene is not a live scene: never made by this library, or freed");
    OK(mb_scene_result_free(result));
    FAILS(mb_scene_result_free(result), MB_STATUS_INVALID_HANDLE,
          "result is not a live scene result: never made by this library, or freed");
    OK(mb_scene_result_free(r2));
    OK(mb_scene_free(s2));
    mb_shape *shapes[] = {ground, small};
    for (size_t i = 0; i < 2; i++) OK(mb_shape_free(shapes[i]));
    mb_motion *motions[] = {still, fall, slow, spin, beside, longer};
    for (size_t i = 0; i < 6; i++) OK(mb_motion_free(motions[i]));
}

/* Shared handles queried from several threads at once; each thread's error
 * message is its own. */
struct shared {
    const mb_shape *ball;
    const mb_motion *a, *b;
    int bad;
};

static void *worker(void *arg) {
    struct shared *s = arg;
    for (int i = 0; i < 40; i++) {
        mb_report r;
        if (mb_time_of_impact(s->ball, s->a, s->ball, s->b, NULL, &r) != MB_STATUS_OK ||
            r.outcome != MB_OUTCOME_CONTACT || !(r.time <= 1.5 && r.time >= 1.5 - 1e-4))
            s->bad++;
        mb_shape *x = NULL;
        if (i % 2 == 0) {
            if (mb_shape_ball(-1.0, &x) != MB_STATUS_INVALID_INPUT ||
                strstr(mb_last_error_message(), "radius") == NULL)
                s->bad++;
        } else {
            if (mb_shape_cylinder(0.0, 1.0, &x) != MB_STATUS_INVALID_INPUT ||
                strstr(mb_last_error_message(), "radius") != NULL)
                s->bad++;
        }
    }
    return NULL;
}

static void test_threads(void) {
    mb_shape *ball = NULL;
    OK(mb_shape_ball(0.5, &ball));
    mb_motion *a = moving(at(-2, 0, 0), v3(1, 0, 0), ZERO, 2.0);
    mb_motion *b = moving(at(2, 0, 0), v3(-1, 0, 0), ZERO, 2.0);
    pthread_t t[4];
    struct shared s[4];
    for (int i = 0; i < 4; i++) {
        s[i] = (struct shared){ball, a, b, 0};
        CHECK(pthread_create(&t[i], NULL, worker, &s[i]) == 0, "thread %d", i);
    }
    for (int i = 0; i < 4; i++) {
        pthread_join(t[i], NULL);
        CHECK(s[i].bad == 0, "thread %d: %d bad answers", i, s[i].bad);
    }
    OK(mb_shape_free(ball));
    OK(mb_motion_free(a));
    OK(mb_motion_free(b));
}

/* Two doubles equal, NaN equal to NaN. */
static int same(double a, double b) { return a == b || (isnan(a) && isnan(b)); }

static int same_vec(mb_vec3 a, mb_vec3 b) {
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

/* Two reports alike in every field. */
static int same_report(mb_report a, mb_report b) {
    return a.outcome == b.outcome && a.criterion == b.criterion && same(a.time, b.time) &&
           same_vec(a.witness_a, b.witness_a) && same_vec(a.witness_b, b.witness_b) &&
           same_vec(a.normal, b.normal) && same(a.distance, b.distance) &&
           same(a.resolution, b.resolution) && a.node_pairs == b.node_pairs &&
           a.triangle_pairs == b.triangle_pairs && a.iterations == b.iterations;
}

/*
 * The batch on every core: 240 pairs (balls of several radii approaching
 * head-on at several gaps and speeds, every sixth pair moving apart, and a
 * mesh cube falling onto the ground every tenth), each answer against its
 * closed form and against the same query made alone, field by field.
 */
static void test_batch(void) {
    enum { N = 240 };
    mb_shape *balls[3] = {NULL, NULL, NULL};
    double radii[3] = {0.25, 0.5, 1.0};
    for (int i = 0; i < 3; i++) OK(mb_shape_ball(radii[i], &balls[i]));
    mb_shape *ground = NULL, *cube = cube_mesh(0.5, MB_MESH_SOLIDITY_AUTO);
    OK(mb_shape_half_space(v3(0, 0, 1), &ground));
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 4.0);
    mb_motion *ma[N], *mb_[N];
    mb_pair_query q[N];
    double gaps[N], speeds[N];
    int kinds[N]; /* 0 approach, 1 apart, 2 cube on ground */
    for (int k = 0; k < N; k++) {
        double ra = radii[k % 3], rb = radii[(k / 3) % 3];
        double gap = 0.5 + 0.05 * (k % 17), speed = 0.5 + 0.25 * (k % 5);
        kinds[k] = k % 10 == 9 ? 2 : (k % 6 == 5 ? 1 : 0);
        gaps[k] = gap;
        speeds[k] = speed;
        if (kinds[k] == 2) {
            /* The cube's bottom (half side 0.5) at gap over the ground. */
            ma[k] = moving(at(0, 0, 0.5 + gap), v3(0, 0, -speed), ZERO, 4.0);
            mb_[k] = NULL;
            q[k] = (mb_pair_query){cube, ma[k], ground, still};
            continue;
        }
        double dir = kinds[k] == 1 ? -1.0 : 1.0;
        ma[k] = moving(at(0, 0, 0), v3(dir * speed / 2, 0, 0), ZERO, 4.0);
        mb_[k] = moving(at(ra + rb + gap, 0, 0), v3(-dir * speed / 2, 0, 0), ZERO, 4.0);
        q[k] = (mb_pair_query){balls[k % 3], ma[k], balls[(k / 3) % 3], mb_[k]};
    }
    mb_report out[N];
    memset(out, 0, sizeof out);
    OK(mb_time_of_impact_batch(q, N, NULL, out));
    mb_params p = mb_params_default();
    for (int k = 0; k < N; k++) {
        char what[64];
        snprintf(what, sizeof what, "batch query %d", k);
        if (kinds[k] == 1) {
            CHECK(out[k].outcome == MB_OUTCOME_SEPARATED, "%s: outcome %d", what,
                  (int)out[k].outcome);
        } else {
            expect_linear(what, out[k], gaps[k], speeds[k], p.contact_distance);
        }
        mb_report alone = toi(q[k].shape_a, q[k].motion_a, q[k].shape_b, q[k].motion_b, NULL);
        CHECK(same_report(alone, out[k]), "%s: the batch says t = %.17g, the query alone %.17g",
              what, out[k].time, alone.time);
    }
    /* A batch of none writes nothing (and may pass NULL arrays). */
    OK(mb_time_of_impact_batch(NULL, 0, NULL, NULL));

    /* Bad batches: the failing query is named, nothing is written. */
    mb_report untouched[3];
    memset(untouched, 0x5a, sizeof untouched);
    mb_pair_query bad[3] = {q[0], q[1], q[2]};
    bad[1].shape_b = NULL;
    FAILS(mb_time_of_impact_batch(bad, 3, NULL, untouched), MB_STATUS_NULL_POINTER,
          "queries[1].shape_b is NULL");
    mb_motion *longer = moving(at(0, 0, 0), ZERO, ZERO, 5.0);
    bad[1] = q[1];
    bad[2].motion_b = longer;
    FAILS(mb_time_of_impact_batch(bad, 3, NULL, untouched), MB_STATUS_QUERY_ERROR,
          "queries[2].motion_a, queries[2].motion_b: the two motions have different "
          "intervals");
    bad[2] = q[2];
    bad[0].shape_a = ground;
    bad[0].shape_b = ground;
    FAILS(mb_time_of_impact_batch(bad, 3, NULL, untouched), MB_STATUS_QUERY_ERROR,
          "queries[0].shape_a, queries[0].shape_b: no stepper takes this pair");
    bad[0] = q[0];
    bad[0].motion_a = (const mb_motion *)ground;
    FAILS(mb_time_of_impact_batch(bad, 3, NULL, untouched), MB_STATUS_INVALID_HANDLE,
          "queries[0].motion_a is a handle of another type (not a motion)");
    FAILS(mb_time_of_impact_batch(q, 3, NULL, NULL), MB_STATUS_NULL_POINTER, "out is NULL");
    FAILS(mb_time_of_impact_batch(NULL, 3, NULL, untouched), MB_STATUS_NULL_POINTER,
          "queries is NULL");
    p.contact_distance = -1.0;
    FAILS(mb_time_of_impact_batch(q, 3, &p, untouched), MB_STATUS_INVALID_PARAMETER,
          "params: parameter out of range: contact_distance");
    unsigned char *bytes = (unsigned char *)untouched;
    int written = 0;
    for (size_t i = 0; i < sizeof untouched; i++) written |= bytes[i] != 0x5a;
    CHECK(!written, "a failing batch wrote to out");

    for (int k = 0; k < N; k++) {
        OK(mb_motion_free(ma[k]));
        if (mb_[k]) OK(mb_motion_free(mb_[k]));
    }
    for (int i = 0; i < 3; i++) OK(mb_shape_free(balls[i]));
    OK(mb_shape_free(ground));
    OK(mb_shape_free(cube));
    OK(mb_motion_free(still));
    OK(mb_motion_free(longer));
}

/*
 * A cube (a closed mesh) resting 0.5 d above the plate (d the contact
 * distance): mb_time_of_impact says initial contact; mb_past_contact says
 * never deeper when it slides or lifts, and when pressed down at 1 m/s,
 * a time after the start when the cube is within d of the half-space
 * 1.5 d past the plane that separated them: between (gap + 0.5 d) / v and
 * (gap + 1.5 d) / v. Bad arguments are named.
 */
static void test_past_contact(void) {
    const double d = 1e-3, gap = 0.5e-3, h = 0.1;
    mb_params p = mb_params_default();
    p.contact_distance = d;
    mb_shape *cube = cube_mesh(h, MB_MESH_SOLIDITY_AUTO);
    mb_shape *plate = plate_mesh();
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, 1.0 / 60.0);
    const struct {
        const char *what;
        mb_vec3 v, w;
        int deeper;
    } cases[] = {
        {"slides and spins about z", {3, -2, 0}, {0, 0, 40}, 0},
        {"lifts", {1, 0, 2}, {0, 0, 0}, 0},
        {"pressed down", {0, 0, -1}, {0, 0, 0}, 1},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        mb_motion *m = moving(at(0.3, -0.2, h + gap), cases[k].v, cases[k].w, 1.0 / 60.0);
        mb_report r = toi(cube, m, plate, still, &p);
        CHECK(r.outcome == MB_OUTCOME_INITIAL_CONTACT && r.normal.z < -0.99,
              "%s: outcome %d normal z %g", cases[k].what, (int)r.outcome, r.normal.z);
        mb_past_report past;
        OK(mb_past_contact(cube, m, plate, still, r.normal, &p, &past));
        if (cases[k].deeper) {
            double lo = (gap + 0.5 * d) / 1.0, hi = (gap + 1.5 * d) / 1.0;
            CHECK(past.outcome == MB_PAST_OUTCOME_AT && past.time >= lo * (1 - 1e-9) &&
                      past.time <= hi * (1 + 1e-9),
                  "%s: outcome %d time %g not in [%g, %g]", cases[k].what, (int)past.outcome,
                  past.time, lo, hi);
        } else {
            CHECK(past.outcome == MB_PAST_OUTCOME_NEVER && isnan(past.time),
                  "%s: outcome %d time %g", cases[k].what, (int)past.outcome, past.time);
        }
        mb_motion_free(m);
    }
    /* Both turning: not decided. */
    mb_motion *spin = moving(at(0, 0, h + gap), ZERO, v3(0, 0, 1), 1.0 / 60.0);
    mb_motion *plate_spin = moving(at(0, 0, 0), ZERO, v3(0, 1, 0), 1.0 / 60.0);
    mb_past_report past;
    OK(mb_past_contact(cube, spin, plate, plate_spin, v3(0, 0, -1), NULL, &past));
    CHECK(past.outcome == MB_PAST_OUTCOME_UNDECIDED, "both turning: outcome %d",
          (int)past.outcome);
    /* Bad arguments, each named. */
    mb_motion *unit = moving(at(0, 0, 1), ZERO, ZERO, 1.0);
    FAILS(mb_past_contact(NULL, spin, plate, still, v3(0, 0, -1), NULL, &past),
          MB_STATUS_NULL_POINTER, "shape_a is NULL");
    FAILS(mb_past_contact(cube, spin, plate, NULL, v3(0, 0, -1), NULL, &past),
          MB_STATUS_NULL_POINTER, "motion_b is NULL");
    FAILS(mb_past_contact(cube, spin, plate, still, v3(0, 0, -1), NULL, NULL),
          MB_STATUS_NULL_POINTER, "out is NULL");
    FAILS(mb_past_contact(cube, spin, plate, still, ZERO, NULL, &past), MB_STATUS_INVALID_INPUT,
          "normal: the zero vector");
    FAILS(mb_past_contact(cube, spin, plate, still, v3(NAN, 0, 0), NULL, &past),
          MB_STATUS_INVALID_INPUT, "normal.x");
    FAILS(mb_past_contact(cube, unit, plate, still, v3(0, 0, -1), NULL, &past),
          MB_STATUS_QUERY_ERROR, "motion_a, motion_b");
    mb_params bad = p;
    bad.contact_distance = -1.0;
    FAILS(mb_past_contact(cube, spin, plate, still, v3(0, 0, -1), &bad, &past),
          MB_STATUS_INVALID_PARAMETER, "params");
    mb_motion_free(unit);
    mb_motion_free(plate_spin);
    mb_motion_free(spin);
    mb_motion_free(still);
    mb_shape_free(plate);
    mb_shape_free(cube);
}

/* mb_past_contact_below: a cube resting on the plate (drifting 1e-4 a step)
 * is decided by the closed form, no cast; pressed down at 1 m/s, the time
 * it may reach its ceiling (the start's overlap, or zero, plus d; or the
 * floor) is between its closed-form bounds; a held ceiling is kept; bad
 * arguments are named. */
static void test_past_contact_below(void) {
    const double d = 1e-3, gap = 0.5e-3, h = 0.1, dt = 1.0 / 60.0;
    mb_params p = mb_params_default();
    p.contact_distance = d;
    mb_shape *cube = cube_mesh(h, MB_MESH_SOLIDITY_AUTO);
    mb_shape *plate = plate_mesh();
    mb_motion *still = moving(at(0, 0, 0), ZERO, ZERO, dt);
    mb_motion *rest = moving(at(0.3, -0.2, h + gap), v3(6e-3, 0, -6e-3), ZERO, dt);
    mb_below_report below;
    OK(mb_past_contact_below(cube, rest, plate, still, v3(0, 0, -1), NULL, 0.0, &p, &below));
    CHECK(below.outcome == MB_PAST_OUTCOME_NEVER && below.cast == 0 && below.ceiling.held == 0 &&
              fabs(below.ceiling.value - d) < 1e-9 && fabs(below.overlap + gap) < 1e-9,
          "resting: outcome %d cast %u ceiling %g overlap %g", (int)below.outcome, below.cast,
          below.ceiling.value, below.overlap);
    /* The floor raises the ceiling. */
    OK(mb_past_contact_below(cube, rest, plate, still, v3(0, 0, -1), NULL, 5e-3, &p, &below));
    CHECK(below.outcome == MB_PAST_OUTCOME_NEVER && below.ceiling.value == 5e-3,
          "floor: ceiling %g", below.ceiling.value);
    mb_motion *press = moving(at(0.3, -0.2, h + gap), v3(0, 0, -1), ZERO, dt);
    OK(mb_past_contact_below(cube, press, plate, still, v3(0, 0, -1), NULL, 0.0, &p, &below));
    /* The cast's contact distance is min(d, room / 2), room = d + gap; it
     * answers once within it of the plane at overlap d, never within half. */
    double delta = fmin(d, 0.5 * (d + gap));
    double lo = gap + d - delta, hi = gap + d - 0.5 * delta;
    CHECK(below.outcome == MB_PAST_OUTCOME_AT && below.cast != 0 && below.ceiling.held != 0 &&
              below.time >= lo * (1 - 1e-9) && below.time <= hi * (1 + 1e-9),
          "pressed: outcome %d time %g not in [%g, %g]", (int)below.outcome, below.time, lo, hi);
    /* Held: the ceiling is kept (here below the start's overlap plus d). */
    mb_ceiling last = {0.2e-3, 1};
    OK(mb_past_contact_below(cube, press, plate, still, v3(0, 0, -1), &last, 0.0, &p, &below));
    CHECK(below.ceiling.value == 0.2e-3 && below.outcome == MB_PAST_OUTCOME_AT,
          "held: ceiling %g outcome %d", below.ceiling.value, (int)below.outcome);
    FAILS(mb_past_contact_below(cube, press, plate, still, v3(0, 0, -1), NULL, 0.0, &p, NULL),
          MB_STATUS_NULL_POINTER, "out is NULL");
    FAILS(mb_past_contact_below(cube, press, NULL, still, v3(0, 0, -1), NULL, 0.0, &p, &below),
          MB_STATUS_NULL_POINTER, "shape_b is NULL");
    FAILS(mb_past_contact_below(cube, press, plate, still, ZERO, NULL, 0.0, &p, &below),
          MB_STATUS_INVALID_INPUT, "normal: the zero vector");
    mb_motion_free(press);
    mb_motion_free(rest);
    mb_motion_free(still);
    mb_shape_free(plate);
    mb_shape_free(cube);
}

/* The handle of the motion a value stands for (mb_motion_about_centre of its
 * fields), to read its points and to compare the value entry points with the
 * handle ones. */
static mb_motion *handle_of(mb_motion_value v) {
    mb_motion *m = NULL;
    OK(mb_motion_about_centre(v.centre, v.local_centre, v.rotation, v.linear, v.angular,
                              v.duration, &m));
    return m;
}

static int same_below(mb_below_report a, mb_below_report b) {
    return a.outcome == b.outcome && same(a.time, b.time) && same(a.overlap, b.overlap) && a.ceiling.value == b.ceiling.value &&
           a.ceiling.held == b.ceiling.held && a.cast == b.cast;
}

/* Motions by value (mb_motion_value: no handle): the value between two poses
 * against the closed form (the quarter turn of test_motions); the queries by
 * value answer as the handle ones on the same motion, and as the closed forms
 * (balls head-on, a cube resting on and pressed into the plate); bad values
 * are named by field. */
static void test_motion_values(void) {
    double h = sqrt(0.5);
    mb_pose start = at(0, 0, 0), end = {{2, 0, 0}, {h, 0, 0, h}};
    mb_motion_value v;
    OK(mb_motion_value_between(start, end, 0.5, &v));
    CHECK(fabs(v.linear.x - 4) < 1e-12 && fabs(v.linear.y) < 1e-12 && fabs(v.linear.z) < 1e-12 &&
              fabs(v.angular.z - M_PI) < 1e-12 && fabs(v.angular.x) < 1e-12 &&
              fabs(v.angular.y) < 1e-12 && v.duration == 0.5 && v.centre.x == 0 &&
              v.local_centre.x == 0 && v.rotation.w == 1,
          "between: linear (%g %g %g) angular (%g %g %g) duration %g", v.linear.x, v.linear.y,
          v.linear.z, v.angular.x, v.angular.y, v.angular.z, v.duration);
    mb_motion *m = handle_of(v);
    mb_vec3 p;
    OK(mb_motion_point_at(m, v3(1, 0, 0), 0.5, &p));
    CHECK(fabs(p.x - 2) < 1e-12 && fabs(p.y - 1) < 1e-12 && fabs(p.z) < 1e-12,
          "value's end point (%g %g %g)", p.x, p.y, p.z);
    OK(mb_motion_free(m));
    /* About the body point (1, 0, 0): that point moves on the straight line
     * from (1, 0, 0) to (2, 1, 0); the body origin ends at (2, 0, 0). */
    OK(mb_motion_value_between_about(start, end, 0.5, v3(1, 0, 0), &v));
    CHECK(fabs(v.centre.x - 1) < 1e-12 && fabs(v.linear.x - 2) < 1e-12 &&
              fabs(v.linear.y - 2) < 1e-12 && v.local_centre.x == 1,
          "between about: centre %g linear (%g %g)", v.centre.x, v.linear.x, v.linear.y);
    m = handle_of(v);
    OK(mb_motion_point_at(m, v3(0, 0, 0), 0.5, &p));
    CHECK(fabs(p.x - 2) < 1e-12 && fabs(p.y) < 1e-12, "origin at the end (%g %g)", p.x, p.y);
    OK(mb_motion_free(m));

    /* Balls of radius 0.5 head-on from x = -2 and 2 at 1 each: the gap 3
     * closes at 2 (test_balls_head_on). */
    mb_shape *ball = NULL;
    OK(mb_shape_ball(0.5, &ball));
    mb_motion_value va = {{-2, 0, 0}, ZERO, IDENTITY, {1, 0, 0}, ZERO, 2.0};
    mb_motion_value vb = {{2, 0, 0}, ZERO, IDENTITY, {-1, 0, 0}, ZERO, 2.0};
    mb_params pr = mb_params_default();
    mb_report r, rh;
    OK(mb_time_of_impact_values(ball, &va, ball, &vb, &pr, &r));
    expect_linear("balls by value", r, 3.0, 2.0, pr.contact_distance);
    mb_motion *ha = handle_of(va), *hb = handle_of(vb);
    rh = toi(ball, ha, ball, hb, &pr);
    CHECK(same_report(r, rh), "by value t = %.17g, by handle %.17g", r.time, rh.time);
    OK(mb_motion_free(ha));
    OK(mb_motion_free(hb));

    /* The cube resting on the plate and pressed into it
     * (test_past_contact_below), by value. */
    const double d = 1e-3, gap = 0.5e-3, hc = 0.1, dt = 1.0 / 60.0;
    mb_params pc = mb_params_default();
    pc.contact_distance = d;
    mb_shape *cube = cube_mesh(hc, MB_MESH_SOLIDITY_AUTO);
    mb_shape *plate = plate_mesh();
    mb_motion_value still = {ZERO, ZERO, IDENTITY, ZERO, ZERO, dt};
    mb_motion_value rest = {{0.3, -0.2, hc + gap}, ZERO, IDENTITY, {6e-3, 0, -6e-3}, ZERO, dt};
    mb_motion_value press = {{0.3, -0.2, hc + gap}, ZERO, IDENTITY, {0, 0, -1}, ZERO, dt};
    mb_below_report below, below_h;
    OK(mb_past_contact_below_values(cube, &rest, plate, &still, v3(0, 0, -1), NULL, 0.0, &pc,
                                    &below));
    CHECK(below.outcome == MB_PAST_OUTCOME_NEVER && below.cast == 0 &&
              fabs(below.ceiling.value - d) < 1e-9 && fabs(below.overlap + gap) < 1e-9,
          "resting by value: outcome %d cast %u ceiling %g overlap %g", (int)below.outcome,
          below.cast, below.ceiling.value, below.overlap);
    OK(mb_past_contact_below_values(cube, &press, plate, &still, v3(0, 0, -1), NULL, 0.0, &pc,
                                    &below));
    double delta = fmin(d, 0.5 * (d + gap));
    double lo = gap + d - delta, hi = gap + d - 0.5 * delta;
    CHECK(below.outcome == MB_PAST_OUTCOME_AT && below.cast != 0 && below.ceiling.held != 0 &&
              below.time >= lo * (1 - 1e-9) && below.time <= hi * (1 + 1e-9),
          "pressed by value: outcome %d time %g not in [%g, %g]", (int)below.outcome, below.time,
          lo, hi);
    /* Turned an eighth about x, its centre h sqrt(2) + gap above the plate:
     * its lowest edge is gap above it (the value's rotation is used). */
    double c8 = cos(M_PI / 8), s8 = sin(M_PI / 8);
    mb_motion_value turned = {{0.3, -0.2, hc * sqrt(2.0) + gap}, ZERO, {c8, s8, 0, 0},
                              {6e-3, 0, -6e-3}, ZERO, dt};
    OK(mb_past_contact_below_values(cube, &turned, plate, &still, v3(0, 0, -1), NULL, 0.0, &pc,
                                    &below));
    CHECK(below.outcome == MB_PAST_OUTCOME_NEVER && fabs(below.overlap + gap) < 1e-9,
          "turned by value: outcome %d overlap %g", (int)below.outcome, below.overlap);
    mb_motion *hp = handle_of(press), *hs = handle_of(still);
    mb_ceiling last = {0.2e-3, 1};
    for (int k = 0; k < 2; k++) {
        const mb_ceiling *l = k ? &last : NULL;
        OK(mb_past_contact_below_values(cube, &press, plate, &still, v3(0, 0, -1), l, 0.0, &pc,
                                        &below));
        OK(mb_past_contact_below(cube, hp, plate, hs, v3(0, 0, -1), l, 0.0, &pc, &below_h));
        CHECK(same_below(below, below_h), "ceiling %d: by value t = %g, by handle %g", k,
              below.time, below_h.time);
    }
    OK(mb_motion_free(hp));
    OK(mb_motion_free(hs));

    /* Bad values and pointers, named; nothing written. */
    mb_motion_value bad = press;
    bad.linear.y = NAN;
    memset(&r, 0, sizeof r);
    mb_report before_r = r;
    FAILS(mb_time_of_impact_values(cube, &press, plate, &bad, &pc, &r), MB_STATUS_INVALID_INPUT,
          "motion_b.linear.y is not finite (got NaN)");
    CHECK(memcmp(&r, &before_r, sizeof r) == 0, "the report was written on failure");
    bad = press;
    bad.rotation = (mb_quat){0, 0, 0, 0};
    FAILS(mb_past_contact_below_values(cube, &bad, plate, &still, v3(0, 0, -1), NULL, 0.0, &pc,
                                       &below),
          MB_STATUS_INVALID_INPUT, "motion_a.rotation: quaternion has zero length");
    bad = press;
    bad.duration = 0;
    FAILS(mb_time_of_impact_values(cube, &bad, plate, &still, &pc, &r), MB_STATUS_INVALID_INPUT,
          "motion_a.duration must be positive and finite (got 0)");
    bad = still;
    bad.duration = 2 * dt;
    FAILS(mb_time_of_impact_values(cube, &press, plate, &bad, &pc, &r), MB_STATUS_QUERY_ERROR,
          "motion_a, motion_b");
    FAILS(mb_time_of_impact_values(cube, NULL, plate, &still, &pc, &r), MB_STATUS_NULL_POINTER,
          "motion_a is NULL");
    FAILS(mb_past_contact_below_values(cube, &press, plate, NULL, v3(0, 0, -1), NULL, 0.0, &pc,
                                       &below),
          MB_STATUS_NULL_POINTER, "motion_b is NULL");
    FAILS(mb_past_contact_below_values(cube, &press, plate, &still, ZERO, NULL, 0.0, &pc, &below),
          MB_STATUS_INVALID_INPUT, "normal: the zero vector");
    FAILS(mb_past_contact_below_values(cube, &press, plate, &still, v3(0, 0, -1), NULL, 0.0, &pc,
                                       NULL),
          MB_STATUS_NULL_POINTER, "out is NULL");
    FAILS(mb_motion_value_between(start, end, 0.0, &v), MB_STATUS_INVALID_INPUT,
          "duration must be positive and finite (got 0)");
    FAILS(mb_motion_value_between_about(start, end, 0.5, v3(0, NAN, 0), &v),
          MB_STATUS_INVALID_INPUT, "local_centre.y is not finite (got NaN)");
    FAILS(mb_motion_value_between(start, end, 0.5, NULL), MB_STATUS_NULL_POINTER, "out is NULL");
    mb_shape_free(plate);
    mb_shape_free(cube);
    mb_shape_free(ball);
}

int main(void) {
    CHECK(strcmp(mb_last_error_message(), "") == 0, "a message before any failure");
    test_version_and_params();
    test_balls_head_on();
    test_convex_on_ground();
    test_spinning_rod();
    test_meshes();
    test_compound();
    test_motions();
    test_bad_handles_and_params();
    test_scene();
    test_threads();
    test_batch();
    test_past_contact();
    test_past_contact_below();
    test_motion_values();
    if (failures) {
        fprintf(stderr, "%d of %d checks FAILED\n", failures, checks);
        return 1;
    }
    CHECK(message_checks >= 30, "only %d messages checked", message_checks);
    printf("all %d checks passed (the messages of %d failing calls among them)\n", checks,
           message_checks);
    return 0;
}
