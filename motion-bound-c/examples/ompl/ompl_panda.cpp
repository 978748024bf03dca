// OMPL's RRT-Connect from C++ for the Panda in MotionBenchMaker's scenes, with
// motion-bound's certified edge check as OMPL's MotionValidator (through the C
// ABI, motion_bound.h), side by side with OMPL's DiscreteMotionValidator at two
// resolutions on the same states. Built and run by ../ompl.sh, which writes the
// scenes from data/mbm/*.json as plain text (see it for the format).
//
// Per scene and validator one line:
//   scene S validator V: solved N of M, median ms X, touching K
// `touching`: returned paths (RRT-Connect's, not simplified) of which some
// sample, at most --fine-step rad apart in every joint along each segment,
// touches an obstacle by mb_chain_scene_collides_at on a mesh-only scene of the
// same obstacles (boxes as their 12 triangles, cylinders as 64-sided prisms
// inscribed in them: a touch of the prism is a touch of the cylinder; link
// pairs not counted).
//
// Usage: ompl_panda URDF SCENE_FILE... [--plans 30] [--timeout 10] [--seed 1]
//        [--fine-step 1e-3] [--validators ours,discrete:0.01,discrete:0.005]

#include "motion_bound.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

constexpr int ARM = 7;       // planned joints
constexpr int DOF = 9;       // with the two fingers
constexpr double FINGERS = 0.04;

void check(mb_status s, const char *what) {
    if (s != MB_STATUS_OK)
        throw std::runtime_error(std::string(what) + ": " + mb_last_error_message());
}

// The arm's seven joints of an OMPL state, with the fingers open.
std::array<double, DOF> q_of(const ob::State *s) {
    const auto *v = s->as<ob::RealVectorStateSpace::StateType>();
    std::array<double, DOF> q{};
    for (int i = 0; i < ARM; i++) q[i] = v->values[i];
    q[ARM] = q[ARM + 1] = FINGERS;
    return q;
}

// The static check every validator shares: no checked pair's surfaces meet
// at q (mb_chain_scene_collides_at, every obstacle kind), and the certified
// clearance there (mb_chain_scene_clearance) for clearance objectives.
class Valid : public ob::StateValidityChecker {
  public:
    Valid(const ob::SpaceInformationPtr &si, const mb_chain_scene *scene)
        : ob::StateValidityChecker(si), scene_(scene) {}
    bool isValid(const ob::State *s) const override {
        auto q = q_of(s);
        uint8_t collides = 1;
        return mb_chain_scene_collides_at(scene_, q.data(), DOF, &collides) ==
                   MB_STATUS_OK &&
               collides == 0;
    }
    double clearance(const ob::State *s) const override {
        auto q = q_of(s);
        double d = 0.0;
        if (mb_chain_scene_clearance(scene_, q.data(), DOF, &d, nullptr) != MB_STATUS_OK)
            return 0.0;
        return d > 0.0 ? d : 0.0;
    }

  private:
    const mb_chain_scene *scene_;
};

// The certified motion validator: an edge is valid when motion-bound
// certifies the whole joint-space segment free (every obstacle and checked
// link pair), not only samples of it.
class CertifiedMotionValidator : public ob::MotionValidator {
  public:
    CertifiedMotionValidator(const ob::SpaceInformationPtr &si,
                             const mb_chain_scene *scene)
        : ob::MotionValidator(si), scene_(scene) {}

    bool checkMotion(const ob::State *a, const ob::State *b) const override {
        auto qa = q_of(a), qb = q_of(b);
        uint8_t free_ = 0;
        bool ok = mb_chain_scene_edge_is_free(scene_, qa.data(), qb.data(), DOF,
                                              &free_) == MB_STATUS_OK &&
                  free_ == 1;
        (ok ? valid_ : invalid_)++;
        return ok;
    }

    // The last valid state: where the edge is certified free up to.
    bool checkMotion(const ob::State *a, const ob::State *b,
                     std::pair<ob::State *, double> &last) const override {
        auto qa = q_of(a), qb = q_of(b);
        mb_edge_report r;
        bool ok = mb_chain_scene_check_edge(scene_, qa.data(), qb.data(), DOF, &r) ==
                      MB_STATUS_OK &&
                  r.outcome == MB_EDGE_OUTCOME_FREE;
        if (!ok) {
            double t = r.outcome == MB_EDGE_OUTCOME_FREE ? 0.0 : r.free_until;
            if (!(t >= 0.0 && t <= 1.0)) t = 0.0;
            if (last.first != nullptr)
                si_->getStateSpace()->interpolate(a, b, t, last.first);
            last.second = t;
        }
        (ok ? valid_ : invalid_)++;
        return ok;
    }

  private:
    const mb_chain_scene *scene_;
};

struct Obstacle {
    std::string kind, name;
    mb_pose pose;
    double a, b, c;  // a box's half extents; a cylinder's half length, radius
};

struct Scene {
    std::string name;
    std::array<double, ARM> start{}, goal{};
    std::vector<Obstacle> obstacles;
};

// SCENE_FILE: `name S`, `start q1..q7`, `goal q1..q7`, then
// `box NAME x y z qw qx qy qz hx hy hz` and
// `cylinder NAME x y z qw qx qy qz half_length radius` (along the pose's y).
Scene read_scene(const std::string &path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    Scene s;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        std::string key;
        l >> key;
        if (key == "name") {
            l >> s.name;
        } else if (key == "start" || key == "goal") {
            auto &q = key == "start" ? s.start : s.goal;
            for (auto &x : q) l >> x;
        } else if (key == "box" || key == "cylinder") {
            Obstacle o;
            o.kind = key;
            o.c = 0;
            l >> o.name >> o.pose.translation.x >> o.pose.translation.y >>
                o.pose.translation.z >> o.pose.rotation.w >> o.pose.rotation.x >>
                o.pose.rotation.y >> o.pose.rotation.z >> o.a >> o.b;
            if (key == "box") l >> o.c;
            s.obstacles.push_back(o);
        }
        if (!key.empty() && l.fail()) throw std::runtime_error(path + ": bad line: " + line);
    }
    return s;
}

mb_shape *mesh_of(const Obstacle &o) {
    std::vector<double> v;
    std::vector<uint32_t> f;
    if (o.kind == "box") {
        for (int i = 0; i < 8; i++) {
            v.push_back(i & 4 ? o.a : -o.a);
            v.push_back(i & 2 ? o.b : -o.b);
            v.push_back(i & 1 ? o.c : -o.c);
        }
        f = {0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5, 0, 4, 5, 0, 5, 1,
             2, 3, 7, 2, 7, 6, 0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3};
    } else {
        // The 64-sided prism inscribed in the cylinder (along y).
        const int n = 64;
        for (int side = 0; side < 2; side++)
            for (int i = 0; i < n; i++) {
                double t = 2 * M_PI * i / n;
                v.push_back(o.b * std::cos(t));
                v.push_back(side ? o.a : -o.a);
                v.push_back(o.b * std::sin(t));
            }
        v.insert(v.end(), {0, -o.a, 0, 0, o.a, 0});
        for (uint32_t i = 0; i < n; i++) {
            uint32_t j = (i + 1) % n;
            f.insert(f.end(), {i, n + i, n + j, i, n + j, j, 2 * n, i, j,
                               2 * n + 1, n + j, n + i});
        }
    }
    mb_shape *s = nullptr;
    check(mb_shape_mesh(v.data(), v.size() / 3, f.data(), f.size() / 3,
                        MB_MESH_SOLIDITY_HOLLOW, &s),
          "mb_shape_mesh");
    return s;
}

// The planning scene (shapes, exact) or the fine check's (meshes, link pairs
// not checked).
mb_chain_scene *make_scene(const mb_chain *chain, const Scene &s, bool meshes) {
    mb_chain_scene *scene = nullptr;
    check(mb_chain_scene_new(chain, &scene), "mb_chain_scene_new");
    for (const auto &o : s.obstacles) {
        mb_shape *shape = nullptr;
        if (meshes) {
            shape = mesh_of(o);
        } else if (o.kind == "box") {
            check(mb_shape_cuboid(mb_vec3{o.a, o.b, o.c}, &shape), "mb_shape_cuboid");
        } else {
            check(mb_shape_cylinder(o.a, o.b, &shape), "mb_shape_cylinder");
        }
        check(mb_chain_scene_add_obstacle(scene, shape, o.pose, o.name.c_str(), nullptr),
              "mb_chain_scene_add_obstacle");
        mb_shape_free(shape);
    }
    if (meshes) {
        size_t n = 0;
        check(mb_chain_link_count(chain, &n), "mb_chain_link_count");
        for (size_t a = 0; a < n; a++)
            for (size_t b = a + 1; b < n; b++) {
                const char *na = nullptr, *nb = nullptr;
                check(mb_chain_link_name(chain, a, &na), "mb_chain_link_name");
                check(mb_chain_link_name(chain, b, &nb), "mb_chain_link_name");
                check(mb_chain_scene_allow_collision(scene, na, nb),
                      "mb_chain_scene_allow_collision");
            }
    }
    return scene;
}

// Whether some sample of the path, at most `step` apart in every joint,
// touches an obstacle of the mesh-only scene.
bool touches(const mb_chain_scene *meshes, const std::vector<std::array<double, DOF>> &path,
             double step) {
    for (size_t k = 0; k + 1 < path.size(); k++) {
        const auto &a = path[k], &b = path[k + 1];
        double longest = 0;
        for (int i = 0; i < ARM; i++) longest = std::max(longest, std::fabs(b[i] - a[i]));
        long n = std::max(2L, static_cast<long>(std::ceil(longest / step)) + 1);
        for (long j = 0; j < n; j++) {
            double t = static_cast<double>(j) / (n - 1);
            std::array<double, DOF> q{};
            for (int i = 0; i < DOF; i++) q[i] = a[i] + t * (b[i] - a[i]);
            uint8_t hit = 0;
            check(mb_chain_scene_collides_at(meshes, q.data(), DOF, &hit),
                  "mb_chain_scene_collides_at");
            if (hit) return true;
        }
    }
    return false;
}

struct Plan {
    bool solved;
    double ms;
    std::vector<std::array<double, DOF>> path;
};

Plan plan_once(const mb_chain_scene *scene, const std::string &validator,
               const Scene &s, const double *lo, const double *hi, double timeout) {
    auto space = std::make_shared<ob::RealVectorStateSpace>(ARM);
    ob::RealVectorBounds bounds(ARM);
    for (int i = 0; i < ARM; i++) {
        bounds.setLow(i, lo[i]);
        bounds.setHigh(i, hi[i]);
    }
    space->setBounds(bounds);
    og::SimpleSetup ss(space);
    auto si = ss.getSpaceInformation();
    ss.setStateValidityChecker(std::make_shared<Valid>(si, scene));
    if (validator == "ours") {
        si->setMotionValidator(std::make_shared<CertifiedMotionValidator>(si, scene));
    } else {
        // "discrete:R": OMPL's DiscreteMotionValidator (the default) at R.
        si->setStateValidityCheckingResolution(std::stod(validator.substr(9)));
    }
    ob::ScopedState<> start(space), goal(space);
    for (int i = 0; i < ARM; i++) {
        start[i] = s.start[i];
        goal[i] = s.goal[i];
    }
    ss.setStartAndGoalStates(start, goal);
    ss.setPlanner(std::make_shared<og::RRTConnect>(si));
    auto clock = std::chrono::steady_clock::now();
    ob::PlannerStatus solved = ss.solve(timeout);
    double ms = std::chrono::duration<double, std::milli>(
                    std::chrono::steady_clock::now() - clock)
                    .count();
    Plan p{bool(solved) && ss.haveExactSolutionPath(), ms, {}};
    if (p.solved) {
        const auto &path = ss.getSolutionPath();
        for (std::size_t k = 0; k < path.getStateCount(); k++) p.path.push_back(q_of(path.getState(k)));
    }
    return p;
}

}  // namespace

int main(int argc, char **argv) {
    std::vector<std::string> files;
    std::string urdf;
    int plans = 30;
    double timeout = 10.0, fine = 1e-3;
    unsigned seed = 1;
    std::string validators = "ours,discrete:0.01,discrete:0.005";
    for (int i = 1; i < argc; i++) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--plans") plans = std::stoi(next());
        else if (a == "--timeout") timeout = std::stod(next());
        else if (a == "--seed") seed = static_cast<unsigned>(std::stoul(next()));
        else if (a == "--fine-step") fine = std::stod(next());
        else if (a == "--validators") validators = next();
        else if (urdf.empty()) urdf = a;
        else files.push_back(a);
    }
    if (urdf.empty() || files.empty()) {
        std::fprintf(stderr, "usage: ompl_panda URDF SCENE_FILE... [--plans N] [--timeout S] "
                             "[--seed N] [--fine-step R] [--validators LIST]\n");
        return 2;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG::setSeed(seed);  // once, before any sampling: the runs are repeatable
    mb_chain *panda = nullptr;
    check(mb_chain_from_urdf_file(urdf.c_str(), nullptr, &panda), "the Panda");
    double lo[DOF], hi[DOF];
    check(mb_chain_limits(panda, lo, hi, DOF), "mb_chain_limits");
    std::vector<std::string> names;
    {
        std::stringstream l(validators);
        std::string v;
        while (std::getline(l, v, ',')) names.push_back(v);
    }
    int status = 0;
    for (const auto &file : files) {
        Scene s = read_scene(file);
        mb_chain_scene *shapes = make_scene(panda, s, false);
        mb_chain_scene *meshes = make_scene(panda, s, true);
        for (const auto &v : names) {
            std::vector<double> ms;
            int solved = 0, touching = 0;
            for (int k = 0; k < plans; k++) {
                Plan p = plan_once(shapes, v, s, lo, hi, timeout);
                ms.push_back(p.ms);
                if (p.solved) {
                    solved++;
                    touching += touches(meshes, p.path, fine);
                }
            }
            std::sort(ms.begin(), ms.end());
            double median = ms.size() % 2 ? ms[ms.size() / 2]
                                          : 0.5 * (ms[ms.size() / 2 - 1] + ms[ms.size() / 2]);
            std::printf("scene %s validator %s: solved %d of %d, median ms %.1f, touching %d\n",
                        s.name.c_str(), v.c_str(), solved, plans, median, touching);
            std::fflush(stdout);
            if (v == "ours" && touching > 0) status = 1;
        }
        mb_chain_scene_free(shapes);
        mb_chain_scene_free(meshes);
    }
    mb_chain_free(panda);
    return status;
}
