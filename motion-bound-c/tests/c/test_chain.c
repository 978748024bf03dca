/*
 * The C ABI's chains (mb_chain_*, mb_chain_scene_*): a two-joint arm from URDF
 * text against closed forms (the angle at which a turning bar meets a thin
 * pole, bracketed by geometry), bad input of every kind (bad URDF, wrong joint
 * count, NaN, out-of-limit configurations, unknown link names, NULL, freed and
 * mistyped handles), allowed pairs, threads querying one scene at once against
 * the serial answers, and the Panda read from data/ (MB_DATA_DIR). The answers
 * against the crate's own API, bit for bit, are in ../chain.rs. Built and run
 * under AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer by
 * ../run_c_tests.sh. Exit code 0 when every check passes, 1 otherwise.
 */
#include "motion_bound.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
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

#define OK(call) CHECK((call) == MB_STATUS_OK, "%s", #call)
/* A call that must fail with `status` and a message containing `part`. */
#define FAILS(call, status, part)                                              \
    do {                                                                       \
        mb_status s_ = (call);                                                 \
        CHECK(s_ == (status), "%s gave %d, expected %d", #call, (int)s_,      \
              (int)(status));                                                  \
        CHECK(strstr(mb_last_error_message(), (part)) != NULL,                 \
              "the message after %s does not name %s", #call, (part));         \
    } while (0)

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* base (a 0.1 cube) -j1 (about z, [-3, 3])-> arm (a bar 1 long along x)
 * -j2 (about z at x = 1, [-2, 2])-> fore (a bar 1 long). */
static const char *ARM_URDF =
    "<robot name=\"arm\">"
    " <link name=\"base\"><collision><geometry><box size=\"0.1 0.1 0.1\"/>"
    "  </geometry></collision></link>"
    " <link name=\"arm\"><collision><origin xyz=\"0.5 0 0\"/><geometry>"
    "  <box size=\"1.0 0.04 0.04\"/></geometry></collision></link>"
    " <link name=\"fore\"><collision><origin xyz=\"0.5 0 0\"/><geometry>"
    "  <box size=\"1.0 0.04 0.04\"/></geometry></collision></link>"
    " <joint name=\"j1\" type=\"revolute\"><parent link=\"base\"/>"
    "  <child link=\"arm\"/><axis xyz=\"0 0 1\"/>"
    "  <limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>"
    " <joint name=\"j2\" type=\"revolute\"><parent link=\"arm\"/>"
    "  <child link=\"fore\"/><origin xyz=\"1 0 0\"/><axis xyz=\"0 0 1\"/>"
    "  <limit lower=\"-2\" upper=\"2\" effort=\"1\" velocity=\"1\"/></joint>"
    "</robot>";

/* The pole: a 0.01 square in x, y, 2 tall, its axis 0.7 from j1's at 45 deg. */
#define POLE_R 0.7
#define POLE_H 0.005
static mb_pose pole_pose(void) {
    mb_pose p = {{POLE_R * cos(M_PI / 4), POLE_R * sin(M_PI / 4), 0.0},
                 {1.0, 0.0, 0.0, 0.0}};
    return p;
}

static mb_chain *arm_chain(void) {
    mb_chain *c = NULL;
    OK(mb_chain_from_urdf_string(ARM_URDF, NULL, NULL, &c));
    return c;
}

/* The pole's 8 corners and 12 triangles, wound outward. */
static mb_shape *pole_mesh(void) {
    double v[24];
    for (int i = 0; i < 8; i++) {
        v[3 * i + 0] = (i & 4) ? POLE_H : -POLE_H;
        v[3 * i + 1] = (i & 2) ? POLE_H : -POLE_H;
        v[3 * i + 2] = (i & 1) ? 1.0 : -1.0;
    }
    static const uint32_t f[36] = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5,
                                   0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6,
                                   0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    mb_shape *s = NULL;
    OK(mb_shape_mesh(v, 8, f, 12, MB_MESH_SOLIDITY_AUTO, &s));
    return s;
}

/* The shape scene: the pole as a box, a point cloud at -45 deg, a floor. */
static mb_chain_scene *shape_scene(const mb_chain *chain) {
    mb_chain_scene *s = NULL;
    OK(mb_chain_scene_new(chain, &s));
    mb_shape *pole = NULL, *floor = NULL;
    mb_vec3 h = {POLE_H, POLE_H, 1.0};
    OK(mb_shape_cuboid(h, &pole));
    size_t index = 99;
    OK(mb_chain_scene_add_obstacle(s, pole, pole_pose(), "pole", &index));
    CHECK(index == 0, "the pole is obstacle %zu", index);
    mb_vec3 cloud[3];
    for (int i = 0; i < 3; i++) {
        double r = 0.45 + 0.05 * i;
        cloud[i].x = r * cos(-M_PI / 4);
        cloud[i].y = r * sin(-M_PI / 4);
        cloud[i].z = 0.0;
    }
    OK(mb_chain_scene_add_points(s, cloud, 3, 0.01, "camera", &index));
    CHECK(index == 1, "the cloud is obstacle %zu", index);
    mb_vec3 up = {0.0, 0.0, 1.0};
    OK(mb_shape_half_space(up, &floor));
    mb_pose below = {{0.0, 0.0, -0.5}, {1.0, 0.0, 0.0, 0.0}};
    OK(mb_chain_scene_add_obstacle(s, floor, below, NULL, NULL));
    OK(mb_shape_free(pole));
    OK(mb_shape_free(floor));
    return s;
}

static void test_chain_from_urdf(void) {
    mb_chain *c = arm_chain();
    size_t n = 0;
    OK(mb_chain_dof(c, &n));
    CHECK(n == 2, "dof %zu", n);
    OK(mb_chain_link_count(c, &n));
    CHECK(n == 3, "links %zu", n);
    OK(mb_chain_link_index(c, "fore", &n));
    const char *name = NULL;
    OK(mb_chain_link_name(c, n, &name));
    CHECK(name != NULL && strcmp(name, "fore") == 0, "link %zu is %s", n, name);
    FAILS(mb_chain_link_name(c, 3, &name), MB_STATUS_OUT_OF_RANGE, "index");
    FAILS(mb_chain_link_index(c, "hand", &n), MB_STATUS_UNKNOWN_NAME, "hand");
    double lo[2], hi[2];
    OK(mb_chain_limits(c, lo, hi, 2));
    CHECK(lo[0] == -3.0 && hi[0] == 3.0 && lo[1] == -2.0 && hi[1] == 2.0,
          "limits [%g, %g], [%g, %g]", lo[0], hi[0], lo[1], hi[1]);
    FAILS(mb_chain_limits(c, lo, hi, 3), MB_STATUS_INVALID_SIZE, "dof");
    FAILS(mb_chain_limits(c, NULL, hi, 2), MB_STATUS_NULL_POINTER, "lower");

    /* Bad URDFs. */
    mb_chain *bad = NULL;
    FAILS(mb_chain_from_urdf_string("this is not XML", NULL, NULL, &bad),
          MB_STATUS_INVALID_URDF, "text");
    CHECK(bad == NULL, "nothing written on failure");
    FAILS(mb_chain_from_urdf_string(
              "<robot name=\"r\"><link name=\"a\"><collision><geometry>"
              "<mesh filename=\"no_such_mesh.stl\"/></geometry></collision>"
              "</link></robot>",
              "/nonexistent", NULL, &bad),
          MB_STATUS_INVALID_URDF, "no_such_mesh");
    FAILS(mb_chain_from_urdf_string(
              "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/>"
              "<joint name=\"j\" type=\"floating\"><parent link=\"a\"/>"
              "<child link=\"b\"/></joint></robot>",
              NULL, NULL, &bad),
          MB_STATUS_INVALID_URDF, "j");
    FAILS(mb_chain_from_urdf_file("/nonexistent/robot.urdf", NULL, &bad),
          MB_STATUS_INVALID_URDF, "/nonexistent/robot.urdf");
    FAILS(mb_chain_from_urdf_string(NULL, NULL, NULL, &bad),
          MB_STATUS_NULL_POINTER, "text");
    FAILS(mb_chain_from_urdf_string(ARM_URDF, NULL, NULL, NULL),
          MB_STATUS_NULL_POINTER, "NULL");
    CHECK(bad == NULL, "nothing written on failure");

    /* Handles: NULL, freed, mistyped. */
    FAILS(mb_chain_dof(NULL, &n), MB_STATUS_NULL_POINTER, "chain");
    mb_chain_scene *s = NULL;
    OK(mb_chain_scene_new(c, &s));
    FAILS(mb_chain_dof((const mb_chain *)(const void *)s, &n),
          MB_STATUS_INVALID_HANDLE, "chain");
    OK(mb_chain_free(c));
    FAILS(mb_chain_dof(c, &n), MB_STATUS_INVALID_HANDLE, "chain");
    FAILS(mb_chain_free(c), MB_STATUS_INVALID_HANDLE, "chain");
    FAILS(mb_chain_scene_new(c, &s), MB_STATUS_INVALID_HANDLE, "chain");
    OK(mb_chain_free(NULL));
    /* The scene kept its own copy of the freed chain. */
    double q0[2] = {0.0, 0.0}, q1[2] = {0.3, 0.0};
    uint8_t free_ = 0;
    OK(mb_chain_scene_edge_is_free(s, q0, q1, 2, &free_));
    CHECK(free_ == 1, "an empty scene's edge is free");
    OK(mb_chain_scene_free(s));
    FAILS(mb_chain_scene_edge_is_free(s, q0, q1, 2, &free_),
          MB_STATUS_INVALID_HANDLE, "scene");
    OK(mb_chain_scene_free(NULL));
}

static void test_queries_against_geometry(void) {
    mb_chain *c = arm_chain();
    mb_chain_scene *shapes = shape_scene(c);
    mb_chain_scene *meshes = NULL;
    OK(mb_chain_scene_new(c, &meshes));
    mb_shape *pole = pole_mesh();
    OK(mb_chain_scene_add_obstacle(meshes, pole, pole_pose(), "pole", NULL));
    OK(mb_shape_free(pole));

    /* The bar (half width 0.02) turning from 0 to 1.5 rad meets the pole
     * (within 0.005 sqrt 2 of its axis, 0.7 from j1's at pi/4) between the
     * angle at which its axis is 0.02 + 0.00708 + the contact distance from
     * the bar's midline and that at which it is 0.02 - 0.00708 from it. */
    double contact = 1e-3, reach = POLE_H * sqrt(2.0);
    double earliest = M_PI / 4 - asin((0.02 + reach + contact + 1e-6) / POLE_R);
    double latest = M_PI / 4 - asin((0.02 - reach) / POLE_R);
    double q0[2] = {0.0, 0.0}, q1[2] = {1.5, 0.0}, back[2] = {-1.5, 0.0};
    uint8_t free_ = 9;
    OK(mb_chain_scene_edge_is_free(shapes, q0, q1, 2, &free_));
    CHECK(free_ == 0, "the sweep through the pole is not free");
    OK(mb_chain_scene_edge_is_free(shapes, q0, back, 2, &free_));
    CHECK(free_ == 0, "the sweep through the point cloud is not free");
    OK(mb_chain_scene_edge_is_free(meshes, q0, back, 2, &free_));
    CHECK(free_ == 1, "the sweep away from the pole is free");

    mb_edge_report e;
    OK(mb_chain_scene_check_edge(shapes, q0, q1, 2, &e));
    CHECK(e.outcome == MB_EDGE_OUTCOME_CONTACT, "outcome %d", (int)e.outcome);
    CHECK(e.pair.kind == MB_CHAIN_PAIR_KIND_OBSTACLE && e.pair.b == 0 &&
              e.pair.a == 1,
          "pair %d (%zu, %zu)", (int)e.pair.kind, e.pair.a, e.pair.b);
    CHECK(e.free_until <= e.at && 1.5 * e.at <= latest &&
              1.5 * e.at >= earliest - 0.05,
          "at %.6f (angle %.6f), free until %.6f, angle in [%.6f, %.6f]", e.at,
          1.5 * e.at, e.free_until, earliest, latest);
    OK(mb_chain_scene_check_edge(shapes, q0, back, 2, &e));
    CHECK(e.outcome == MB_EDGE_OUTCOME_CONTACT && e.pair.b == 1,
          "the cloud: outcome %d obstacle %zu", (int)e.outcome, e.pair.b);
    OK(mb_chain_scene_check_edge(meshes, q0, back, 2, &e));
    CHECK(e.outcome == MB_EDGE_OUTCOME_FREE && e.free_until == 1.0 &&
              isnan(e.at) && e.pair.kind == MB_CHAIN_PAIR_KIND_NONE,
          "free: outcome %d", (int)e.outcome);

    mb_segment_report r;
    OK(mb_chain_scene_check_segment(meshes, q0, q1, 2, &r));
    double angle = 1.5 * r.time;
    CHECK(r.outcome == MB_SEGMENT_OUTCOME_CONTACT && angle >= earliest &&
              angle <= latest,
          "contact angle %.6f not in [%.6f, %.6f]", angle, earliest, latest);
    CHECK(r.pair.kind == MB_CHAIN_PAIR_KIND_OBSTACLE && r.pair.a == 1 &&
              r.pair.b == 0,
          "pair %d (%zu, %zu)", (int)r.pair.kind, r.pair.a, r.pair.b);
    /* The witnesses: on the bar (within its half width of its midline at
     * that angle) and on the pole (within its half size of its axis). */
    double ux = cos(angle), uy = sin(angle);
    double off = fabs(-r.point_a.x * uy + r.point_a.y * ux);
    CHECK(off <= 0.02 * sqrt(2.0) + 1e-9, "witness on the bar %.6f off", off);
    double dx = r.point_b.x - pole_pose().translation.x;
    double dy = r.point_b.y - pole_pose().translation.y;
    CHECK(fabs(dx) <= POLE_H + 1e-9 && fabs(dy) <= POLE_H + 1e-9,
          "witness on the pole (%g, %g) off its axis", dx, dy);
    double wd = sqrt(pow(r.point_a.x - r.point_b.x, 2) +
                     pow(r.point_a.y - r.point_b.y, 2) +
                     pow(r.point_a.z - r.point_b.z, 2));
    CHECK(fabs(wd - r.distance) <= 1e-9 && r.distance <= contact + 1e-9,
          "witness distance %g, reported %g", wd, r.distance);
    OK(mb_chain_scene_check_segment(meshes, q0, back, 2, &r));
    CHECK(r.outcome == MB_SEGMENT_OUTCOME_SEPARATED && isnan(r.time),
          "separated: %d", (int)r.outcome);
    /* Every query takes every obstacle kind (issue 63): the first contact
     * with the pole as a cuboid, never later than the first touch, and with
     * the point cloud the other way. */
    OK(mb_chain_scene_check_segment(shapes, q0, q1, 2, &r));
    CHECK(r.outcome == MB_SEGMENT_OUTCOME_CONTACT && 1.5 * r.time <= latest &&
              1.5 * r.time >= earliest - 0.05 && r.pair.b == 0 &&
              r.distance <= contact + 1e-9,
          "shapes: outcome %d angle %.6f pair %zu distance %g", (int)r.outcome,
          1.5 * r.time, r.pair.b, r.distance);
    OK(mb_chain_scene_check_segment(shapes, q0, back, 2, &r));
    CHECK(r.outcome == MB_SEGMENT_OUTCOME_CONTACT && r.pair.b == 1,
          "the cloud: outcome %d obstacle %zu", (int)r.outcome, r.pair.b);

    /* The static check and the clearance, against the closed form. */
    double through[2] = {M_PI / 4, 0.0};
    OK(mb_chain_scene_collides_at(shapes, through, 2, &free_));
    CHECK(free_ == 1, "the bar through the pole collides");
    OK(mb_chain_scene_collides_at(shapes, q0, 2, &free_));
    CHECK(free_ == 0, "the bar along x does not");
    double d = NAN;
    mb_chain_pair p;
    OK(mb_chain_scene_clearance(meshes, q0, 2, &d, &p));
    /* At q = 0 the pole's nearest point (0.4950 - 0.005, 0.4950 - 0.005) is
     * 0.4900 - 0.02 from the bar's top face. */
    double exact = POLE_R * sin(M_PI / 4) - POLE_H - 0.02;
    CHECK(d <= exact && d >= exact - 1e-3 && p.kind == MB_CHAIN_PAIR_KIND_OBSTACLE,
          "clearance %.6f, exact %.6f", d, exact);
    FAILS(mb_chain_scene_clearance(meshes, q0, 2, NULL, &p),
          MB_STATUS_NULL_POINTER, "out_distance");
    /* With shapes: never above the pole's distance (the cloud is nearer). */
    OK(mb_chain_scene_clearance(shapes, q0, 2, &d, &p));
    CHECK(d <= exact && d > 0.2 && p.kind == MB_CHAIN_PAIR_KIND_OBSTACLE,
          "clearance with shapes %.6f, the pole's %.6f", d, exact);
    size_t allowed = 9;
    OK(mb_chain_scene_allow_collisions_at(shapes, q0, 2, 0.0, &allowed));
    CHECK(allowed == 0, "no link pair touches: %zu", allowed);

    /* Bad configurations: each message names the argument and index. */
    double nan_q[2] = {0.0, NAN}, out_q[2] = {3.5, 0.0}, inf_q[2] = {INFINITY, 0};
    FAILS(mb_chain_scene_edge_is_free(shapes, q0, q1, 3, &free_),
          MB_STATUS_INVALID_SIZE, "dof is 3");
    FAILS(mb_chain_scene_edge_is_free(shapes, q0, q1, 1, &free_),
          MB_STATUS_INVALID_SIZE, "2 joint coordinates");
    FAILS(mb_chain_scene_edge_is_free(shapes, nan_q, q1, 2, &free_),
          MB_STATUS_INVALID_INPUT, "q0[1] is not finite");
    FAILS(mb_chain_scene_check_edge(shapes, q0, inf_q, 2, &e),
          MB_STATUS_INVALID_INPUT, "q1[0] is not finite");
    FAILS(mb_chain_scene_check_segment(meshes, q0, out_q, 2, &r),
          MB_STATUS_INVALID_INPUT, "q1[0] is outside joint \"j1\"'s limits");
    FAILS(mb_chain_scene_collides_at(shapes, nan_q, 2, &free_),
          MB_STATUS_INVALID_INPUT, "q[1]");
    FAILS(mb_chain_scene_edge_is_free(shapes, NULL, q1, 2, &free_),
          MB_STATUS_NULL_POINTER, "q0");
    FAILS(mb_chain_scene_edge_is_free(shapes, q0, q1, 2, NULL),
          MB_STATUS_NULL_POINTER, "NULL");
    /* Out of limits is checked only with within_limits on. */
    mb_chain_params params = mb_chain_params_default();
    CHECK(params.within_limits == 1 && params.contact_distance == 1e-3,
          "defaults");
    params.within_limits = 0;
    OK(mb_chain_scene_set_params(meshes, &params));
    OK(mb_chain_scene_check_segment(meshes, q0, out_q, 2, &r));
    OK(mb_chain_scene_set_params(meshes, NULL));
    params = mb_chain_params_default();
    params.contact_distance = -1.0;
    FAILS(mb_chain_scene_set_params(meshes, &params), MB_STATUS_INVALID_PARAMETER,
          "params.contact_distance");
    params = mb_chain_params_default();
    params.padding = NAN;
    FAILS(mb_chain_scene_set_params(meshes, &params), MB_STATUS_INVALID_PARAMETER,
          "params.padding");
    params = mb_chain_params_default();
    params.edge_budget = 0;
    FAILS(mb_chain_scene_set_params(meshes, &params), MB_STATUS_INVALID_PARAMETER,
          "params.edge_budget");

    /* Obstacles refused. */
    double hull_pts[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mb_shape *hull = NULL, *ball = NULL, *compound = NULL;
    OK(mb_shape_convex_hull(hull_pts, 4, &hull));
    FAILS(mb_chain_scene_add_obstacle(meshes, hull, pole_pose(), NULL, NULL),
          MB_STATUS_QUERY_ERROR, "convex hull");
    OK(mb_shape_ball(0.1, &ball));
    mb_shape *parts[1] = {ball};
    mb_pose here = pole_pose();
    OK(mb_shape_compound(parts, &here, 1, &compound));
    FAILS(mb_chain_scene_add_obstacle(meshes, compound, pole_pose(), NULL, NULL),
          MB_STATUS_QUERY_ERROR, "compound");
    mb_pose zero_q = {{0, 0, 0}, {0, 0, 0, 0}};
    FAILS(mb_chain_scene_add_obstacle(meshes, ball, zero_q, NULL, NULL),
          MB_STATUS_INVALID_INPUT, "pose");
    FAILS(mb_chain_scene_add_obstacle(meshes, (const mb_shape *)(const void *)c,
                                      pole_pose(), NULL, NULL),
          MB_STATUS_INVALID_HANDLE, "shape");
    mb_vec3 bad_pts[2] = {{0, 0, 0}, {0, NAN, 0}};
    FAILS(mb_chain_scene_add_points(meshes, bad_pts, 2, 0.01, NULL, NULL),
          MB_STATUS_INVALID_INPUT, "points[1].y");
    FAILS(mb_chain_scene_add_points(meshes, bad_pts, 1, -0.01, NULL, NULL),
          MB_STATUS_INVALID_INPUT, "radius");
    FAILS(mb_chain_scene_add_points(meshes, bad_pts, 0, 0.01, NULL, NULL),
          MB_STATUS_INVALID_SIZE, "count");
    OK(mb_shape_free(hull));
    OK(mb_shape_free(ball));
    OK(mb_shape_free(compound));

    /* The batch: the same answers as one call per edge, on any number of
     * threads; a bad end named by edge, end and coordinate. */
    enum { N = 24 };
    double edges[N * 4];
    uint8_t one[N], batch[N];
    for (int i = 0; i < N; i++) {
        double a = -2.5 + 5.0 * i / N;
        edges[4 * i + 0] = a;
        edges[4 * i + 1] = 0.1 * (i % 5);
        edges[4 * i + 2] = a + 0.6;
        edges[4 * i + 3] = -0.1 * (i % 3);
        OK(mb_chain_scene_edge_is_free(shapes, &edges[4 * i], &edges[4 * i + 2],
                                       2, &one[i]));
    }
    int blocked = 0;
    for (int i = 0; i < N; i++) blocked += one[i] == 0;
    CHECK(blocked > 0 && blocked < N, "%d of %d edges blocked", blocked, N);
    size_t threads[3] = {0, 1, 3};
    for (int k = 0; k < 3; k++) {
        memset(batch, 7, sizeof batch);
        OK(mb_chain_scene_edges_are_free(shapes, edges, N, 2, threads[k], batch));
        CHECK(memcmp(one, batch, N) == 0, "the batch on %zu threads differs",
              threads[k]);
    }
    OK(mb_chain_scene_edges_are_free(shapes, edges, 0, 2, 0, NULL));
    edges[4 * 5 + 3] = NAN;
    FAILS(mb_chain_scene_edges_are_free(shapes, edges, N, 2, 2, batch),
          MB_STATUS_INVALID_INPUT, "edges[5][1][1] is not finite");
    edges[4 * 5 + 3] = 0.0;
    edges[4 * 7 + 0] = -3.2;
    FAILS(mb_chain_scene_edges_are_free(shapes, edges, N, 2, 2, batch),
          MB_STATUS_INVALID_INPUT, "edges[7][0][0] is outside");
    FAILS(mb_chain_scene_edges_are_free(shapes, edges, N, 3, 2, batch),
          MB_STATUS_INVALID_SIZE, "dof is 3");
    FAILS(mb_chain_scene_edges_are_free(shapes, edges, SIZE_MAX / 2, 2, 2, batch),
          MB_STATUS_INVALID_SIZE, "count");

    OK(mb_chain_scene_free(shapes));
    OK(mb_chain_scene_free(meshes));
    OK(mb_chain_free(c));
}

static void test_allowed_pairs(void) {
    mb_chain *c = arm_chain();
    mb_chain_scene *s = NULL;
    OK(mb_chain_scene_new(c, &s));
    uint8_t on = 9;
    OK(mb_chain_scene_checks_pair(s, "base", "arm", &on));
    CHECK(on == 0, "adjacent links are not checked");
    OK(mb_chain_scene_checks_pair(s, "arm", "fore", &on));
    CHECK(on == 0, "adjacent links are not checked");
    OK(mb_chain_scene_checks_pair(s, "fore", "base", &on));
    CHECK(on == 1, "base and fore are checked");
    OK(mb_chain_scene_checks_pair(s, "fore", "fore", &on));
    CHECK(on == 0, "a link with itself is not a pair");
    FAILS(mb_chain_scene_checks_pair(s, "fore", "gripper", &on),
          MB_STATUS_UNKNOWN_NAME, "link_b: no link named \"gripper\"");
    FAILS(mb_chain_scene_allow_collision(s, "hand", "base"),
          MB_STATUS_UNKNOWN_NAME, "link_a: no link named \"hand\"");
    FAILS(mb_chain_scene_allow_collision(s, NULL, "base"),
          MB_STATUS_NULL_POINTER, "link_a");
    OK(mb_chain_scene_allow_collision(s, "base", "fore"));
    OK(mb_chain_scene_checks_pair(s, "fore", "base", &on));
    CHECK(on == 0, "an allowed pair is not checked");
    const char *name = NULL;
    OK(mb_chain_scene_link_name(s, 2, &name));
    CHECK(strcmp(name, "fore") == 0, "link 2 is %s", name);
    FAILS(mb_chain_scene_link_name(s, 5, &name), MB_STATUS_OUT_OF_RANGE, "index");

    /* Pairs touching at a configuration: with j2 folded to 2 rad the fore
     * bar's midline passes sin 2 = 0.909 from j1's axis, its far end
     * sqrt(2 + 2 cos 2) = 1.08 from it: base (within 0.0867 of the axis)
     * stays more than 0.8 away from the bar (half width 0.02), so a distance
     * of 0.5 allows nothing and 2 allows base and fore. */
    mb_chain_scene *t = NULL;
    OK(mb_chain_scene_new(c, &t));
    double folded[2] = {0.0, 2.0};
    size_t count = 99;
    OK(mb_chain_scene_allow_collisions_at(t, folded, 2, 0.5, &count));
    CHECK(count == 0, "%zu pairs within 0.5", count);
    OK(mb_chain_scene_allow_collisions_at(t, folded, 2, 2.0, &count));
    CHECK(count == 1, "%zu pairs within 2", count);
    OK(mb_chain_scene_checks_pair(t, "base", "fore", &on));
    CHECK(on == 0, "the pair within 2 is allowed");
    FAILS(mb_chain_scene_allow_collisions_at(t, folded, 2, -1.0, &count),
          MB_STATUS_INVALID_INPUT, "distance");
    FAILS(mb_chain_scene_allow_collisions_at(t, folded, 1, 1.0, &count),
          MB_STATUS_INVALID_SIZE, "dof");
    OK(mb_chain_scene_free(t));
    OK(mb_chain_scene_free(s));
    OK(mb_chain_free(c));
}

/* Threads: several query one scene at once; each answer must equal the
 * serial one, and each thread's errors stay its own. */
enum { PER_THREAD = 16, THREADS = 4 };
struct job {
    const mb_chain_scene *scene;
    double edges[PER_THREAD * 4];
    uint8_t expected[PER_THREAD];
    int wrong;
    int message_ok;
};

static void *worker(void *arg) {
    struct job *j = arg;
    for (int i = 0; i < PER_THREAD; i++) {
        uint8_t free_ = 9;
        if (mb_chain_scene_edge_is_free(j->scene, &j->edges[4 * i],
                                        &j->edges[4 * i + 2], 2,
                                        &free_) != MB_STATUS_OK ||
            free_ != j->expected[i])
            j->wrong++;
    }
    double nan_q[2] = {NAN, 0.0};
    uint8_t out;
    j->message_ok =
        mb_chain_scene_collides_at(j->scene, nan_q, 2, &out) ==
            MB_STATUS_INVALID_INPUT &&
        strstr(mb_last_error_message(), "q[0]") != NULL;
    return NULL;
}

static void test_threads(void) {
    mb_chain *c = arm_chain();
    mb_chain_scene *s = shape_scene(c);
    static struct job jobs[THREADS];
    for (int t = 0; t < THREADS; t++) {
        jobs[t].scene = s;
        jobs[t].wrong = 0;
        jobs[t].message_ok = 0;
        for (int i = 0; i < PER_THREAD; i++) {
            double a = -2.6 + 0.08 * (t * PER_THREAD + i);
            double *e = &jobs[t].edges[4 * i];
            e[0] = a;
            e[1] = 0.3 * sin(a);
            e[2] = a + 0.4;
            e[3] = -0.2;
            OK(mb_chain_scene_edge_is_free(s, e, e + 2, 2, &jobs[t].expected[i]));
        }
    }
    pthread_t th[THREADS];
    for (int t = 0; t < THREADS; t++)
        CHECK(pthread_create(&th[t], NULL, worker, &jobs[t]) == 0, "thread %d", t);
    for (int t = 0; t < THREADS; t++) pthread_join(th[t], NULL);
    for (int t = 0; t < THREADS; t++) {
        CHECK(jobs[t].wrong == 0, "thread %d: %d answers differ", t, jobs[t].wrong);
        CHECK(jobs[t].message_ok, "thread %d: its own error message", t);
    }
    OK(mb_chain_scene_free(s));
    OK(mb_chain_free(c));
}

/* The Panda from data/: its meshes resolved beside the URDF. */
static void test_panda(void) {
#ifdef MB_DATA_DIR
    mb_chain *panda = NULL;
    OK(mb_chain_from_urdf_file(MB_DATA_DIR "/arms/franka_panda/panda.urdf", NULL,
                               &panda));
    if (panda == NULL) return;
    size_t dof = 0;
    OK(mb_chain_dof(panda, &dof));
    CHECK(dof == 9, "the Panda has %zu coordinates", dof);
    mb_chain_scene *s = NULL;
    OK(mb_chain_scene_new(panda, &s));
    mb_shape *table = NULL;
    mb_vec3 h = {0.4, 0.6, 0.02};
    OK(mb_shape_cuboid(h, &table));
    mb_pose top = {{0.6, 0.0, 0.3}, {1.0, 0.0, 0.0, 0.0}};
    OK(mb_chain_scene_add_obstacle(s, table, top, "table", NULL));
    OK(mb_shape_free(table));
    /* The ready pose (MotionBenchMaker's start), its hand 0.1 over the
     * table, then the arm tilted 1.7 rad forward, nearly straight: from the
     * shoulder (z 0.333) it falls 0.13 per unit of reach, through the table
     * top (z 0.28 to 0.32) 0.2 to 1 in front. */
    double up[9] = {0, -0.785, 0, -2.356, 0, 1.571, 0.785, 0.04, 0.04};
    double down[9] = {0, 1.7, 0, -0.1, 0, 1.6, 0.8, 0.04, 0.04};
    double edges[4 * 9];
    memcpy(edges, up, sizeof up);
    memcpy(edges + 9, down, sizeof down);
    memcpy(edges + 18, up, sizeof up);
    memcpy(edges + 27, up, sizeof up);
    edges[27 + 0] = 0.3;
    uint8_t one[2], batch[2];
    OK(mb_chain_scene_edge_is_free(s, edges, edges + 9, 9, &one[0]));
    OK(mb_chain_scene_edge_is_free(s, edges + 18, edges + 27, 9, &one[1]));
    CHECK(one[0] == 0 && one[1] == 1, "Panda edges: %d %d", one[0], one[1]);
    OK(mb_chain_scene_edges_are_free(s, edges, 2, 9, 2, batch));
    CHECK(memcmp(one, batch, 2) == 0, "the Panda batch differs");
    uint8_t hit = 9;
    OK(mb_chain_scene_collides_at(s, down, 9, &hit));
    CHECK(hit == 1, "the folded arm is in the table");
    double beyond[9] = {0, -0.785, 0, 0.5, 0, 1.571, 0.785, 0.04, 0.04};
    FAILS(mb_chain_scene_edge_is_free(s, up, beyond, 9, &hit),
          MB_STATUS_INVALID_INPUT, "q1[3] is outside joint \"panda_joint4\"'s limits");
    OK(mb_chain_scene_free(s));
    OK(mb_chain_free(panda));
#endif
}

int main(void) {
    test_chain_from_urdf();
    test_queries_against_geometry();
    test_allowed_pairs();
    test_threads();
    test_panda();
    printf("chain C tests: %d checks, %d failed\n", checks, failures);
    return failures == 0 ? 0 : 1;
}
