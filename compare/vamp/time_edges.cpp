// Times VAMP's own edge check, vamp::planning::validate_motion<vamp::robots::Panda, 8, 32>, on a list of
// edges in one MotionBenchMaker scene (data/mbm/<set>.json). Not part of CI; see README.md beside this file.
//
//   time_edges SCENE.json EDGES.txt [--verdicts OUT.txt] [--self-verdicts OUT.txt] [--reps 5]
//
// EDGES.txt: one edge per line, 14 whitespace-separated numbers, q0[7] then q1[7] (radians); blank lines
// and lines starting with '#' are skipped. VAMP works in f32: the f64 values are rounded to f32.
// The scene: cuboids as VAMP's Cuboid (axes = the columns of "rotation", i.e. the body x, y, z axes in the
// world), cylinders as VAMP's capsules (VAMP's own loader, vamp.problem_dict_to_vamp, adds MBM cylinders
// with add_capsule; VAMP's collision check has no exact cylinder), spheres as spheres. Shapes go to the
// z-aligned lists by the same tests as VAMP's Python Environment.add_cuboid / add_capsule.
//
// Timing: the whole list is checked --reps times (default 5), each edge timed on its own with
// steady_clock; an edge's time is its minimum over the repetitions; mean and p99 are over those per-edge
// minima. The min-of-reps total (the list timed as a whole, no clock per edge) is printed on a second line.
// Verdicts: 1 = in collision (validate_motion returned false), 0 = free. VAMP's check includes the Panda
// sphere model's self-collision pairs; --self-verdicts writes the verdicts of the same check against an
// empty environment (untimed), so that edges rejected by self-collision alone can be told apart.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cctype>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <vamp/collision/factory.hh>
#include <vamp/planning/validate.hh>
#include <vamp/robots/panda.hh>

using Robot = vamp::robots::Panda;
static constexpr std::size_t rake = 8;
static constexpr std::size_t resolution = 32;
static_assert(Robot::resolution == resolution, "the Panda's planner resolution");
using EnvironmentInput = vamp::collision::Environment<float>;
using EnvironmentVector = vamp::collision::Environment<vamp::FloatVector<rake>>;

// ---- a minimal JSON reader (objects, arrays, strings without escapes beyond \" \\ \/, numbers, literals)
struct Json
{
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    double number = 0;
    bool boolean = false;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    auto operator[](const std::string &k) const -> const Json &
    {
        auto it = object.find(k);
        if (kind != Object or it == object.end())
        {
            throw std::runtime_error("JSON: missing key " + k);
        }
        return it->second;
    }
    auto operator[](std::size_t i) const -> const Json &
    {
        if (kind != Array or i >= array.size())
        {
            throw std::runtime_error("JSON: bad index");
        }
        return array[i];
    }
    auto num() const -> double
    {
        if (kind != Number)
        {
            throw std::runtime_error("JSON: not a number");
        }
        return number;
    }
};

struct Parser
{
    const std::string &s;
    std::size_t i = 0;

    void ws()
    {
        while (i < s.size() and std::isspace(static_cast<unsigned char>(s[i])))
        {
            ++i;
        }
    }
    void expect(char c)
    {
        ws();
        if (i >= s.size() or s[i] != c)
        {
            throw std::runtime_error(std::string("JSON: expected ") + c + " at " + std::to_string(i));
        }
        ++i;
    }
    auto str() -> std::string
    {
        expect('"');
        std::string out;
        while (i < s.size() and s[i] != '"')
        {
            if (s[i] == '\\')
            {
                ++i;
            }
            out.push_back(s[i++]);
        }
        ++i;
        return out;
    }
    auto value() -> Json
    {
        ws();
        Json j;
        if (s[i] == '{')
        {
            j.kind = Json::Object;
            ++i;
            ws();
            if (s[i] == '}')
            {
                ++i;
                return j;
            }
            while (true)
            {
                auto k = str();
                expect(':');
                j.object[k] = value();
                ws();
                if (s[i] == ',')
                {
                    ++i;
                    continue;
                }
                expect('}');
                return j;
            }
        }
        if (s[i] == '[')
        {
            j.kind = Json::Array;
            ++i;
            ws();
            if (s[i] == ']')
            {
                ++i;
                return j;
            }
            while (true)
            {
                j.array.push_back(value());
                ws();
                if (s[i] == ',')
                {
                    ++i;
                    continue;
                }
                expect(']');
                return j;
            }
        }
        if (s[i] == '"')
        {
            j.kind = Json::String;
            j.string = str();
            return j;
        }
        for (const char *lit : {"true", "false", "null"})
        {
            if (s.compare(i, std::strlen(lit), lit) == 0)
            {
                i += std::strlen(lit);
                j.kind = lit[0] == 'n' ? Json::Null : Json::Bool;
                j.boolean = lit[0] == 't';
                return j;
            }
        }
        char *end = nullptr;
        j.number = std::strtod(s.c_str() + i, &end);  // correctly rounded f64
        if (end == s.c_str() + i)
        {
            throw std::runtime_error("JSON: bad value at " + std::to_string(i));
        }
        j.kind = Json::Number;
        i = static_cast<std::size_t>(end - s.c_str());
        return j;
    }
};

static auto read_file(const std::string &path) -> std::string
{
    std::ifstream f(path);
    if (not f)
    {
        throw std::runtime_error("cannot read " + path);
    }
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

static inline auto f32(double x) -> float
{
    return static_cast<float>(x);
}

static auto vec3(const Json &j) -> std::array<double, 3>
{
    return {j[0].num(), j[1].num(), j[2].num()};
}

// ---- the scene as VAMP's environment
static auto load_scene(const Json &scene, std::size_t &n_cuboids, std::size_t &n_capsules, std::size_t &n_spheres)
    -> EnvironmentInput
{
    namespace vc = vamp::collision;
    namespace vf = vamp::collision::factory;
    EnvironmentInput env;
    for (const auto &c : scene["cuboids"].array)
    {
        const auto p = vec3(c["center"]);
        const auto &r = c["rotation"];
        const auto h = vec3(c["half_extents"]);
        auto R = [&](int row, int col) { return static_cast<float>(r[row][col].num()); };
        // axis k of the box in the world = column k of the body-to-world rotation
        vc::Cuboid<float> cube(
            f32(p[0]), f32(p[1]), f32(p[2]),  //
            R(0, 0), R(1, 0), R(2, 0),              //
            R(0, 1), R(1, 1), R(2, 1),              //
            R(0, 2), R(1, 2), R(2, 2),              //
            f32(h[0]), f32(h[1]), f32(h[2]));
        cube.name = c["name"].string;
        // as vamp's Python Environment.add_cuboid
        (cube.axis_3_z == 1.F ? env.z_aligned_cuboids : env.cuboids).emplace_back(cube);
        ++n_cuboids;
    }
    for (const auto &c : scene["cylinders"].array)
    {
        const auto p = vec3(c["center"]);
        const auto &r = c["rotation"];
        const double h = c["half_length"].num();
        // the cylinder's axis is the body z axis: column 2 of the rotation; end points in f64, then f32
        std::array<double, 3> a{r[0][2].num() * h, r[1][2].num() * h, r[2][2].num() * h};
        auto capsule = vf::capsule::endpoints::flat(
            f32(p[0] + a[0]), f32(p[1] + a[1]), f32(p[2] + a[2]),  //
            f32(p[0] - a[0]), f32(p[1] - a[1]), f32(p[2] - a[2]),  //
            f32(c["radius"].num()));
        capsule.name = c["name"].string;
        // as vamp's Python Environment.add_capsule
        (capsule.xv == 0.F and capsule.yv == 0.F ? env.z_aligned_capsules : env.capsules).emplace_back(capsule);
        ++n_capsules;
    }
    for (const auto &c : scene["spheres"].array)
    {
        const auto p = vec3(c["center"]);
        auto sphere = vf::sphere::flat(f32(p[0]), f32(p[1]), f32(p[2]), f32(c["radius"].num()));
        sphere.name = c["name"].string;
        env.spheres.emplace_back(sphere);
        ++n_spheres;
    }
    env.sort();
    return env;
}

struct Edge
{
    Robot::Configuration q0, q1;
};

static auto load_edges(const std::string &path) -> std::vector<Edge>
{
    std::ifstream f(path);
    if (not f)
    {
        throw std::runtime_error("cannot read " + path);
    }
    std::vector<Edge> edges;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(f, line))
    {
        ++lineno;
        auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos or line[first] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        std::array<double, 14> v;
        for (auto &x : v)
        {
            if (not(ls >> x))
            {
                throw std::runtime_error(path + ":" + std::to_string(lineno) + ": expected 14 numbers");
            }
        }
        Robot::ConfigurationArray a, b;
        for (auto k = 0U; k < 7; ++k)
        {
            a[k] = static_cast<float>(v[k]);
            b[k] = static_cast<float>(v[7 + k]);
        }
        edges.push_back({Robot::Configuration(a), Robot::Configuration(b)});
    }
    return edges;
}

int main(int argc, char **argv)
{
    if (argc < 3)
    {
        std::cerr << "usage: " << argv[0]
                  << " SCENE.json EDGES.txt [--verdicts OUT.txt] [--self-verdicts OUT.txt] [--reps 5]\n";
        return 2;
    }
    std::string verdicts_path, self_verdicts_path;
    int reps = 5;
    for (int k = 3; k < argc; ++k)
    {
        std::string a = argv[k];
        if (a == "--verdicts" and k + 1 < argc)
        {
            verdicts_path = argv[++k];
        }
        else if (a == "--self-verdicts" and k + 1 < argc)
        {
            self_verdicts_path = argv[++k];
        }
        else if (a == "--reps" and k + 1 < argc)
        {
            reps = std::max(1, std::atoi(argv[++k]));
        }
        else
        {
            std::cerr << "unknown argument " << a << "\n";
            return 2;
        }
    }

    const auto text = read_file(argv[1]);
    Parser parser{text};
    const Json scene = parser.value();
    std::size_t n_cuboids = 0, n_capsules = 0, n_spheres = 0;
    const EnvironmentInput env = load_scene(scene, n_cuboids, n_capsules, n_spheres);
    const EnvironmentVector env_v(env);
    const EnvironmentVector empty_v{EnvironmentInput{}};
    const auto edges = load_edges(argv[2]);
    const std::size_t n = edges.size();
    if (n == 0)
    {
        std::cerr << "no edges\n";
        return 2;
    }

    std::vector<double> best(n, 1e300);
    std::vector<unsigned char> verdict(n, 0);
    double best_total = 1e300;
    using clock = std::chrono::steady_clock;
    for (int r = 0; r < reps; ++r)
    {
        // the list as a whole, no clock per edge
        std::size_t colliding = 0;
        const auto t0 = clock::now();
        for (std::size_t e = 0; e < n; ++e)
        {
            colliding += not vamp::planning::validate_motion<Robot, rake, resolution>(
                edges[e].q0, edges[e].q1, env_v);
        }
        const auto t1 = clock::now();
        best_total = std::min(best_total, std::chrono::duration<double, std::micro>(t1 - t0).count());
        // each edge on its own
        std::size_t colliding_again = 0;
        for (std::size_t e = 0; e < n; ++e)
        {
            const auto s = clock::now();
            const bool free = vamp::planning::validate_motion<Robot, rake, resolution>(
                edges[e].q0, edges[e].q1, env_v);
            const auto f = clock::now();
            best[e] = std::min(best[e], std::chrono::duration<double, std::micro>(f - s).count());
            verdict[e] = free ? 0 : 1;
            colliding_again += not free;
        }
        if (colliding != colliding_again)
        {
            std::cerr << "verdicts changed between passes\n";
            return 1;
        }
    }
    std::size_t colliding = 0, self_colliding = 0;
    std::vector<unsigned char> self_verdict(n, 0);
    for (std::size_t e = 0; e < n; ++e)
    {
        colliding += verdict[e];
        // the same check with no obstacle: what the robot model's own (self-collision) pairs reject
        self_verdict[e] =
            not vamp::planning::validate_motion<Robot, rake, resolution>(edges[e].q0, edges[e].q1, empty_v);
        self_colliding += self_verdict[e];
    }
    double sum = 0, sum_free = 0;
    for (std::size_t e = 0; e < n; ++e)
    {
        sum += best[e];
        sum_free += verdict[e] ? 0. : best[e];
    }
    auto sorted = best;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t i99 = std::min(n - 1, static_cast<std::size_t>(std::ceil(0.99 * n)) - 1);
    const std::string name = scene["set"].string;

    std::printf(
        "vamp scene %s: edges %zu, colliding %zu, mean us per edge %.3f, p99 us %.3f\n",
        name.c_str(),
        n,
        colliding,
        sum / n,
        sorted[i99]);
    std::printf(
        "  (%zu cuboids, %zu cylinders as capsules, %zu spheres; per-edge minimum of %d passes; "
        "min-of-%d total / edges %.3f us; max %.3f us; mean us per free edge %.3f, per colliding edge %.3f; "
        "colliding with no obstacle (self) %zu)\n",
        n_cuboids,
        n_capsules,
        n_spheres,
        reps,
        reps,
        best_total / n,
        sorted.back(),
        n > colliding ? sum_free / double(n - colliding) : 0.,
        colliding ? (sum - sum_free) / double(colliding) : 0.,
        self_colliding);
    if (not verdicts_path.empty())
    {
        std::ofstream out(verdicts_path);
        for (auto v : verdict)
        {
            out << int(v) << "\n";
        }
    }
    if (not self_verdicts_path.empty())
    {
        std::ofstream out(self_verdicts_path);
        for (auto v : self_verdict)
        {
            out << int(v) << "\n";
        }
    }
    return 0;
}
