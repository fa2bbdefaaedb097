/* oracle_compare: a run's CSV (usrsub-harness run --out) against the Simbody
 * oracle's, at the oracle's output times, body by body: the distance between
 * the centres of mass, the angle of the rotation between the two frames (so a
 * quaternion and its negative agree), and the differences of the velocity and
 * the angular velocity. Prints the largest of each with where it occurs, and
 * exits 1 when one exceeds its tolerance (docs/testing.md, "The Simbody
 * oracle").
 *
 *   oracle_compare ORACLE.csv RUN.csv --label NAME --position-tol M
 *                  --angle-tol RAD --velocity-tol M/S --angular-velocity-tol RAD/S
 *
 * Exit 0 agree, 1 disagree, 2 cannot compare: a file, a column or an output
 * time of the oracle missing from the run, or an oracle that does not move
 * (less than 100 position tolerances): a comparison of standing bodies would
 * prove nothing. */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Table {
    std::vector<std::string> names;
    std::map<std::string, size_t> column;
    std::vector<std::vector<double>> rows;
};

bool read_csv(const char *path, Table &t)
{
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line)) {
        std::fprintf(stderr, "oracle_compare: cannot read %s\n", path);
        return false;
    }
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');) {
        t.column[name] = t.names.size();
        t.names.push_back(name);
    }
    for (int lineno = 2; std::getline(in, line); ++lineno) {
        std::vector<double> row;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) {
            char *end = nullptr;
            const double v = std::strtod(cell.c_str(), &end);
            if (end == cell.c_str() || *end != '\0' || !std::isfinite(v)) {
                std::fprintf(stderr, "oracle_compare: %s:%d: '%s' is not a finite number\n", path,
                             lineno, cell.c_str());
                return false;
            }
            row.push_back(v);
        }
        if (row.size() != t.names.size()) {
            std::fprintf(stderr, "oracle_compare: %s:%d: %zu values, %zu columns\n", path, lineno,
                         row.size(), t.names.size());
            return false;
        }
        t.rows.push_back(row);
    }
    return true;
}

struct Worst {
    double value = -1, t = 0;
    int body = 0;
    void see(double v, double time, int id)
    {
        if (v > value)
            value = v, t = time, body = id;
    }
};

/* the angle of the rotation between two unit quaternions, whatever their signs */
double rotation_angle(const double *a, const double *b)
{
    /* conj(a) b: the angle from its vector and scalar parts (atan2 keeps
     * small angles exact where acos would not, and needs no unit length) */
    const double x = a[0] * b[1] - a[1] * b[0] - a[2] * b[3] + a[3] * b[2];
    const double y = a[0] * b[2] + a[1] * b[3] - a[2] * b[0] - a[3] * b[1];
    const double z = a[0] * b[3] - a[1] * b[2] + a[2] * b[1] - a[3] * b[0];
    const double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    return 2.0 * std::atan2(std::sqrt(x * x + y * y + z * z), std::fabs(w));
}

}  // namespace

int main(int argc, char **argv)
{
    if (argc < 3)
        return std::fprintf(stderr, "usage: oracle_compare ORACLE.csv RUN.csv --label NAME --position-tol M"
                                    " --angle-tol RAD --velocity-tol M/S --angular-velocity-tol RAD/S\n"), 2;
    std::string label = argv[2];
    double tol[4] = {-1, -1, -1, -1};
    static const char *const tol_names[4] = {"--position-tol", "--angle-tol", "--velocity-tol",
                                             "--angular-velocity-tol"};
    for (int k = 3; k + 1 < argc; k += 2) {
        const std::string a = argv[k];
        if (a == "--label") {
            label = argv[k + 1];
            continue;
        }
        int which = -1;
        for (int j = 0; j < 4; ++j)
            if (a == tol_names[j])
                which = j;
        if (which < 0)
            return std::fprintf(stderr, "oracle_compare: unknown option %s\n", argv[k]), 2;
        tol[which] = std::atof(argv[k + 1]);
    }
    for (int j = 0; j < 4; ++j)
        if (!(tol[j] > 0))
            return std::fprintf(stderr, "oracle_compare: %s must be given, positive\n", tol_names[j]), 2;

    Table oracle, run;
    if (!read_csv(argv[1], oracle) || !read_csv(argv[2], run))
        return 2;
    /* the bodies: each oracle column bodyN.x starts one */
    std::vector<int> bodies;
    for (const std::string &name : oracle.names)
        if (name.size() > 6 && name.compare(0, 4, "body") == 0 && name.compare(name.size() - 2, 2, ".x") == 0)
            bodies.push_back(std::atoi(name.c_str() + 4));
    static const char *const parts[13] = {"x", "y", "z", "q0", "q1", "q2", "q3", "vx", "vy", "vz", "wx", "wy", "wz"};
    std::map<int, std::vector<size_t>> in_oracle, in_run;
    for (int id : bodies)
        for (const char *part : parts) {
            const std::string name = "body" + std::to_string(id) + "." + part;
            if (oracle.column.count(name) == 0 || run.column.count(name) == 0)
                return std::fprintf(stderr, "oracle_compare: %s: column %s missing from %s\n", label.c_str(),
                                    name.c_str(), oracle.column.count(name) == 0 ? argv[1] : argv[2]), 2;
            in_oracle[id].push_back(oracle.column[name]);
            in_run[id].push_back(run.column[name]);
        }
    if (bodies.empty() || oracle.rows.size() < 2 || run.column.count("t") == 0)
        return std::fprintf(stderr, "oracle_compare: %s: nothing to compare\n", label.c_str()), 2;

    Worst worst[4];
    double excursion = 0;
    size_t next = 0;
    const size_t tcol = run.column["t"];
    for (const std::vector<double> &o : oracle.rows) {
        const double t = o[0];
        while (next < run.rows.size() && run.rows[next][tcol] < t - 1e-9)
            ++next;
        if (next == run.rows.size() || std::fabs(run.rows[next][tcol] - t) > 1e-9)
            return std::fprintf(stderr, "oracle_compare: %s: %s has no row at t = %.10g\n", label.c_str(),
                                argv[2], t), 2;
        const std::vector<double> &r = run.rows[next];
        for (int id : bodies) {
            const std::vector<size_t> &co = in_oracle[id], &cr = in_run[id];
            double d[13], qo[4], qr[4];
            for (int j = 0; j < 13; ++j)
                d[j] = o[co[j]] - r[cr[j]];
            for (int j = 0; j < 4; ++j)
                qo[j] = o[co[3 + j]], qr[j] = r[cr[3 + j]];
            worst[0].see(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), t, id);
            worst[1].see(rotation_angle(qo, qr), t, id);
            worst[2].see(std::sqrt(d[7] * d[7] + d[8] * d[8] + d[9] * d[9]), t, id);
            worst[3].see(std::sqrt(d[10] * d[10] + d[11] * d[11] + d[12] * d[12]), t, id);
            const std::vector<double> &o0 = oracle.rows.front();
            excursion = std::max(excursion, std::hypot(o[co[0]] - o0[co[0]], o[co[1]] - o0[co[1]],
                                                       o[co[2]] - o0[co[2]]));
        }
    }
    if (excursion < 100 * tol[0])
        return std::fprintf(stderr, "oracle_compare: %s: the oracle's bodies move %.3g m at most:"
                                    " too little to judge at %.3g m\n", label.c_str(), excursion, tol[0]), 2;
    static const char *const what[4] = {"position", "orientation", "velocity", "angular velocity"};
    static const char *const unit[4] = {"m", "rad", "m/s", "rad/s"};
    int over = 0;
    for (int j = 0; j < 4; ++j) {
        const bool ok = worst[j].value <= tol[j];
        over += !ok;
        std::printf("%s: %-16s largest difference %9.3g %-5s (body %d, t = %g), tolerance %.3g: %s\n",
                    label.c_str(), what[j], worst[j].value, unit[j], worst[j].body, worst[j].t, tol[j],
                    ok ? "agrees" : "DISAGREES");
    }
    std::printf("%s: %zu output times, %zu bodies, largest motion %.3g m: %s\n", label.c_str(),
                oracle.rows.size(), bodies.size(), excursion, over ? "DISAGREES" : "agrees");
    return over ? 1 : 0;
}
