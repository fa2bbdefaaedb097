/* The mechanisms of the oracle: five, each with the numbers of its XML twin
 * (tests/oracle/NAME.xml): SI units (m, kg, s, N), gravity 9.81 along -y.
 * A change here is a change there: the comparison fails on any difference.
 * And the chain of scripts/joint_chain_model.sh, for any number of bars.
 *
 * Speeds are those of the Simbody mobilizer a tree joint becomes, whose F and
 * M frames coincide at t = 0 (simbody_oracle.cpp): REVOLUTE one rate about
 * the common z axis; SPHERICAL the angular velocity of the child relative to
 * the parent, in the joint frame (its J marker's axes, the world's in these
 * models); UNIVERSAL the rate about the parent's pin, then about the child's;
 * CYLINDRICAL the rate about and along the common z axis; TRANSLATIONAL the
 * rate along J's z axis. The XML's initial velocities (world, at each centre
 * of mass) are what Simbody computes from these: `simbody_oracle NAME
 * --initial` prints them. */
#include "oracle_model.h"

#include <cstdio>
#include <cstdlib>

namespace oracle {
namespace {

Orientation euler(double psi, double theta, double phi)
{
    Orientation o;
    o.form = Orientation::EULER313;
    o.angle[0] = psi, o.angle[1] = theta, o.angle[2] = phi;
    return o;
}

/* direction cosines by the marker's x and z axes in world (y = z cross x) */
Orientation cosines(double x0, double x1, double x2, double z0, double z1, double z2)
{
    Orientation o;
    o.form = Orientation::COSINES;
    o.x[0] = x0, o.x[1] = x1, o.x[2] = x2;
    o.z[0] = z0, o.z[1] = z1, o.z[2] = z2;
    o.y[0] = z1 * x2 - z2 * x1, o.y[1] = z2 * x0 - z0 * x2, o.y[2] = z0 * x1 - z1 * x0;
    return o;
}

Marker marker(int id, int body, double x, double y, double z, Orientation o = Orientation())
{
    return Marker{id, body, {x, y, z}, o};
}

/* (a) A pendulum on a revolute joint whose I marker is on ground and J on the
 * body, its axis tilted (3-1-3 angles 0.4, 0.9, 0.2), its centre of mass off
 * the pivot's plane, a full inertia tensor in turned axes; 4 rad/s about the
 * axis at t = 0. */
Model pendulum_i_ground()
{
    Model m;
    m.name = "pendulum_i_ground";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.bodies = {{2, 20, 1.5, 0.02, 0.03, 0.04, 0.002, -0.001, 0.003}};
    m.markers = {
        marker(10, 1, 0.1, 0.2, -0.05, euler(0.4, 0.9, 0.2)),
        marker(20, 2, 0.25, -0.1, 0.05, euler(0.3, 0.5, -0.7)),
        marker(21, 2, 0.1, 0.2, -0.05, euler(0.4, 0.9, 0.2)),
    };
    m.joints = {{1, "REVOLUTE", 10, 21, {4.0}}};
    m.driver_joint = 0;
    return m;
}

/* (b) A spatial double pendulum on two SPHERICAL joints, spun about all three
 * axes at t = 0 so that it moves out of every plane. */
Model double_spherical()
{
    Model m;
    m.name = "double_spherical";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.bodies = {{2, 20, 1.0, 0.010, 0.004, 0.012, 0.001, 0.0, 0.0},
                {3, 30, 0.7, 0.008, 0.003, 0.009, 0.0, 0.0, 0.0005}};
    m.markers = {
        marker(10, 1, 0, 0, 0),
        marker(20, 2, 0.15, -0.2, 0.05),
        marker(21, 2, 0, 0, 0),
        marker(22, 2, 0.3, -0.4, 0.1),
        marker(30, 3, 0.45, -0.7, 0.2, euler(1.0, 0.3, 0.0)),
        marker(31, 3, 0.3, -0.4, 0.1),
    };
    m.joints = {{1, "SPHERICAL", 21, 10, {1.0, 2.0, 3.0}},
                {2, "SPHERICAL", 31, 22, {-3.0, 0.5, 4.0}}};
    m.driver_joint = 0;
    return m;
}

/* (c) A chain: an arm on a REVOLUTE joint to ground (axis turned 0.3 rad about
 * x), a second body on a UNIVERSAL joint at the arm's end, its pins along the
 * world's x (on the arm, J) and y (on the body, I) at t = 0. */
Model revolute_universal()
{
    Model m;
    m.name = "revolute_universal";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.bodies = {{2, 20, 1.2, 0.002, 0.012, 0.013, 0.0005, 0.0, 0.0},
                {3, 30, 0.9, 0.009, 0.002, 0.0095, 0.0003, 0.0002, 0.0}};
    m.markers = {
        marker(10, 1, 0, 0, 0, euler(0.0, 0.3, 0.0)),
        marker(20, 2, 0.15, -0.05, 0.02),
        marker(21, 2, 0, 0, 0, euler(0.0, 0.3, 0.0)),
        marker(22, 2, 0.3, -0.1, 0.04, cosines(0, 1, 0, 1, 0, 0)),
        marker(30, 3, 0.35, -0.35, 0.12),
        marker(31, 3, 0.3, -0.1, 0.04, cosines(0, 0, 1, 0, 1, 0)),
    };
    m.joints = {{1, "REVOLUTE", 21, 10, {2.0}}, {2, "UNIVERSAL", 31, 22, {1.5, -3.0}}};
    m.driver_joint = 0;
    return m;
}

/* (d) A spatial slider-crank, revolute-spherical-universal-translational: a
 * crank about the world's z axis, a rod from its pin (SPHERICAL) to a slider
 * (UNIVERSAL, pins along the world's y on the slider and z on the rod) that
 * slides along the world's x, 80 mm out of the crank's plane. 3 moving bodies
 * (18 coordinates) less 5 + 3 + 4 + 5 = 17 equations leave 1 freedom, and the
 * mechanism has exactly one (the crank's angle places the slider, the rod's
 * direction and, through the universal, its spin): no equation is redundant.
 * Simbody's tree is the crank, the slider and the rod on the slider; the
 * spherical joint closes the loop. The crank turns at 5 rad/s at t = 0. */
Model slider_crank()
{
    Model m;
    m.name = "slider_crank";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.bodies = {{2, 20, 0.5, 0.0004, 0.0012, 0.0015, 0.0001, 0.0, 0.0},
                {3, 30, 0.8, 0.0009, 0.007, 0.0072, 0.0002, 0.0, -0.0003},
                {4, 40, 1.0, 0.001, 0.001, 0.001, 0.0, 0.0, 0.0}};
    m.markers = {
        marker(10, 1, 0, 0, 0),
        marker(11, 1, 0.4, 0, 0.08, cosines(0, 1, 0, 1, 0, 0)),
        marker(20, 2, 0.05, 0.025, 0),
        marker(21, 2, 0, 0, 0),
        marker(22, 2, 0.1, 0.05, 0),
        marker(30, 3, 0.25, 0.025, 0.04),
        marker(31, 3, 0.1, 0.05, 0),
        marker(32, 3, 0.4, 0, 0.08),
        marker(40, 4, 0.4, -0.02, 0.08),
        marker(41, 4, 0.4, 0, 0.08, cosines(0, 1, 0, 1, 0, 0)),
        marker(42, 4, 0.4, 0, 0.08, cosines(0, 0, 1, 0, 1, 0)),
    };
    m.joints = {{1, "REVOLUTE", 21, 10, {5.0}},
                {4, "TRANSLATIONAL", 41, 11, {0.0}},
                {3, "UNIVERSAL", 32, 42, {0.0, 0.0}},
                {2, "SPHERICAL", 31, 22, {}}};
    m.driver_joint = 1;
    return m;
}

/* (e) A sleeve on a CYLINDRICAL joint to a moving arm: the arm turns on a
 * REVOLUTE joint about an axis near the vertical (turned -1.3 rad about x);
 * the sleeve's axis on the arm is turned by 3-1-3 angles 1.2, 1.4, 0.3; the
 * arm at 3 rad/s, the sleeve at 2 rad/s about and 0.1 m/s along its axis. */
Model cylindrical_on_moving()
{
    Model m;
    m.name = "cylindrical_on_moving";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.bodies = {{2, 20, 2.0, 0.004, 0.03, 0.031, 0.001, 0.0, 0.0005},
                {3, 30, 0.6, 0.0006, 0.0005, 0.0004, 0.00005, 0.0, 0.0}};
    m.markers = {
        marker(10, 1, 0, 0, 0, euler(0.0, -1.3, 0.0)),
        marker(20, 2, 0.2, 0.02, -0.01),
        marker(21, 2, 0, 0, 0, euler(0.0, -1.3, 0.0)),
        marker(22, 2, 0.1, 0.05, 0.0, euler(1.2, 1.4, 0.3)),
        marker(30, 3, 0.13, 0.03, 0.01, euler(0.2, 0.1, 0.0)),
        marker(31, 3, 0.1, 0.05, 0.0, euler(1.2, 1.4, 0.3)),
    };
    m.joints = {{1, "REVOLUTE", 21, 10, {3.0}}, {2, "CYLINDRICAL", 31, 22, {2.0, 0.1}}};
    m.driver_joint = 0;
    return m;
}

/* a position as scripts/joint_chain_model.sh prints it (awk's "%.10g"), so
 * that a bar's left end is where the previous one's right end is, bit for bit */
double as_printed(double x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", x);
    return std::strtod(text, nullptr);
}

}  // namespace

/* (f) The chain of scripts/joint_chain_model.sh n: bar i (body i + 1), 1 kg,
 * 0.2 m along x, its centre-of-mass marker 100 i at x = 0.2 (i - 1) + 0.1, its
 * left end 100 i + 1, its right end 100 i + 2; inertias 1e-4 and
 * 0.00333333333333 kg m^2 (the script's digits); joint 1 from bar 1's left end
 * to ground's marker 10 at the origin, joint i from bar i's left end to bar
 * i - 1's right end; released at rest, straight along x. */
Model chain(int n)
{
    Model m;
    m.name = "chain";
    m.ground = 1;
    m.gravity[0] = 0, m.gravity[1] = -9.81, m.gravity[2] = 0;
    m.markers.push_back(marker(10, 1, 0, 0, 0));
    for (int i = 1; i <= n; ++i) {
        const double x = 0.2 * (i - 1);
        const int id = 100 * i;
        m.bodies.push_back({i + 1, id, 1.0, 0.0001, 0.00333333333333, 0.00333333333333, 0.0, 0.0, 0.0});
        m.markers.push_back(marker(id, i + 1, as_printed(x + 0.1), 0, 0));
        m.markers.push_back(marker(id + 1, i + 1, as_printed(x), 0, 0));
        m.markers.push_back(marker(id + 2, i + 1, as_printed(x + 0.2), 0, 0));
        m.joints.push_back({i, "SPHERICAL", id + 1, i == 1 ? 10 : id - 100 + 2, {0.0, 0.0, 0.0}});
    }
    m.driver_joint = 0;
    return m;
}

namespace {

const std::vector<Model> &all_models()
{
    static const std::vector<Model> models = {pendulum_i_ground(), double_spherical(),
                                              revolute_universal(), slider_crank(),
                                              cylindrical_on_moving()};
    return models;
}

}  // namespace

const Model *find_model(const std::string &name)
{
    for (const Model &m : all_models())
        if (m.name == name)
            return &m;
    return nullptr;
}

std::vector<std::string> model_names()
{
    std::vector<std::string> names;
    for (const Model &m : all_models())
        names.push_back(m.name);
    return names;
}

}  // namespace oracle
