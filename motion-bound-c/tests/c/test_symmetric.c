/* Motion that maps a shape onto itself is not motion (proofs/12-shapes.md, Lemma 12.5),
 * through the C ABI: a spinning ball sliding or rolling, a rolling wheel, a capsule and a cone
 * spinning about their axes, 1.01 to 10 contact distances above a floor (a half-space and a
 * cuboid), rounded or not, are separated within three iterations over one engine step; the
 * same motions pushed towards the floor touch, never after the distance falls to half the
 * contact distance. Run by tests/run_c_tests.sh under ASan, UBSan and LeakSanitizer. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "motion_bound.h"

static int failures = 0;
static int checks = 0;

#define CHECK(cond, ...)                                   \
  do {                                                     \
    checks++;                                              \
    if (!(cond)) {                                         \
      failures++;                                          \
      fprintf(stderr, "FAILED %s:%d: ", __FILE__, __LINE__); \
      fprintf(stderr, __VA_ARGS__);                        \
      fprintf(stderr, "\n");                               \
    }                                                      \
  } while (0)

#define OK(call) CHECK((call) == MB_STATUS_OK, "%s: %s", #call, mb_last_error_message())

static const double CONTACT = 1e-4;
static const double DT = 1.0 / 60.0;

/* A unit quaternion turning by `angle` about the unit axis (x, y, z). */
static mb_quat about(double x, double y, double z, double angle) {
  double s = sin(angle / 2.0);
  mb_quat q = {cos(angle / 2.0), x * s, y * s, z * s};
  return q;
}

typedef struct {
  const char *name;
  mb_shape *shape;
  double low; /* the lowest point below the origin */
  mb_quat rotation;
  mb_vec3 linear;
  mb_vec3 angular;
} spin_case;

int main(void) {
  const double r = 0.05;
  for (int rounded = 0; rounded < 2; rounded++) {
    double rounding = rounded ? 0.01 : 0.0;
    double rr = r + rounding;
    mb_shape *ball = NULL, *cyl = NULL, *wheel = NULL, *capsule = NULL, *cone_core = NULL, *cone = NULL;
    OK(mb_shape_ball(rr, &ball));
    OK(mb_shape_cylinder(0.02, r, &cyl));
    OK(mb_shape_capsule(0.2, rr, &capsule));
    OK(mb_shape_cone(0.1, 0.06, &cone_core));
    if (rounded) {
      OK(mb_shape_rounded(cyl, rounding, &wheel));
      OK(mb_shape_rounded(cone_core, rounding, &cone));
    } else {
      wheel = cyl;
      cone = cone_core;
    }
    mb_quat id = {1.0, 0.0, 0.0, 0.0};
    spin_case cases[5] = {
        {"ball sliding and spinning", ball, rr, id, {3.0, 0.0, 1.0}, {14.0, 9.0, -17.0}},
        {"ball rolling", ball, rr, id, {2.0, 0.0, 0.0}, {0.0, 0.0, -2.0 / rr}},
        {"wheel rolling", wheel, rr, about(1.0, 0.0, 0.0, M_PI / 2.0), {3.0, 0.0, 0.0}, {0.0, 0.0, -3.0 / rr}},
        {"capsule spinning", capsule, rr, about(0.0, 0.0, 1.0, -M_PI / 2.0), {0.0, 0.0, 1.5}, {40.0, 0.0, 0.0}},
        {"cone spinning", cone, 0.1 + rounding, id, {1.0, 0.0, -1.0}, {0.0, 30.0, 0.0}},
    };
    mb_shape *plane = NULL, *slab = NULL;
    OK(mb_shape_half_space((mb_vec3){0.0, 1.0, 0.0}, &plane));
    OK(mb_shape_cuboid((mb_vec3){2.0, 0.05, 2.0}, &slab));
    mb_motion *plane_still = NULL, *slab_still = NULL;
    OK(mb_motion_from_velocities((mb_pose){{0.0, 0.0, 0.0}, id}, (mb_vec3){0, 0, 0}, (mb_vec3){0, 0, 0}, DT,
                                 &plane_still));
    OK(mb_motion_from_velocities((mb_pose){{0.0, -0.05, 0.0}, id}, (mb_vec3){0, 0, 0}, (mb_vec3){0, 0, 0}, DT,
                                 &slab_still));
    mb_params params = mb_params_default();
    params.contact_distance = CONTACT;
    const double gaps[3] = {1.01 * CONTACT, 2.0 * CONTACT, 10.0 * CONTACT};
    for (int g = 0; g < 3; g++) {
      for (int c = 0; c < 5; c++) {
        for (int toward = 0; toward < 2; toward++) {
          spin_case k = cases[c];
          mb_vec3 lin = k.linear;
          lin.y -= toward;
          mb_motion *m = NULL;
          /* The cone turns about its centre of mass, a quarter up from its base. */
          mb_vec3 local = {0.0, c == 4 ? -0.05 : 0.0, 0.0};
          mb_vec3 centre = {0.1, gaps[g] + k.low + local.y, -0.1};
          OK(mb_motion_about_centre(centre, local, k.rotation, lin, k.angular, DT, &m));
          for (int f = 0; f < 2; f++) {
            mb_report rep;
            OK(mb_time_of_impact(k.shape, m, f ? slab : plane, f ? slab_still : plane_still, &params, &rep));
            if (!toward) {
              CHECK(rep.outcome == MB_OUTCOME_SEPARATED && rep.iterations <= 3,
                    "%s (rounding %g) at %g above the %s: outcome %d after %u iterations", k.name, rounding,
                    gaps[g], f ? "cuboid" : "half-space", (int)rep.outcome, rep.iterations);
            } else {
              CHECK(rep.outcome == MB_OUTCOME_CONTACT && rep.time <= gaps[g] - CONTACT / 2.0 + 1e-12 &&
                        rep.time >= gaps[g] - CONTACT - 1e-9,
                    "%s (rounding %g) towards the %s from %g: outcome %d at %g", k.name, rounding,
                    f ? "cuboid" : "half-space", gaps[g], (int)rep.outcome, rep.time);
            }
          }
          OK(mb_motion_free(m));
        }
      }
    }
    OK(mb_motion_free(plane_still));
    OK(mb_motion_free(slab_still));
    OK(mb_shape_free(plane));
    OK(mb_shape_free(slab));
    OK(mb_shape_free(ball));
    OK(mb_shape_free(capsule));
    OK(mb_shape_free(cyl));
    OK(mb_shape_free(cone_core));
    if (rounded) {
      OK(mb_shape_free(wheel));
      OK(mb_shape_free(cone));
    }
  }
  printf("test_symmetric: %d checks, %d failed\n", checks, failures);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
