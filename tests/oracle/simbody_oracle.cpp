/* simbody_oracle: builds one of the oracle's mechanisms (oracle_models.cpp)
 * in Simbody, an independent multibody engine, integrates it and writes its
 * trajectory as a CSV in the columns of `usrsub-harness run --out` (time,
 * then per body x y z, the unit quaternion q0..q3 of its frame, v, w; world
 * axes, at the centre of mass), so that a comparison goes column by column
 * (docs/testing.md, "The Simbody oracle").
 *
 *   simbody_oracle NAME --out FILE.csv [--end T] [--interval DT] [--accuracy A] [--time]
 *   simbody_oracle NAME --initial     the XML's v_ic / w_ic of each body
 *   simbody_oracle --list
 *
 * NAME is a model of --list, or `chain --bodies N`: the chain of N bars on
 * spherical joints of scripts/joint_chain_model.sh N. --time adds a line
 * with the wall time of the integration alone (the calls of stepTo: neither
 * the building of the model nor the writing of rows) and Simbody's counts,
 * its realizations of the state to accelerations (its right-hand sides)
 * among them, for the comparison of speed (docs/performance.md, "Against
 * Simbody").
 *
 * Simbody works in joint coordinates: each tree joint is a mobilizer whose F
 * and M frames coincide at t = 0 (the joint frame W, below), so the model
 * starts where its markers place it; a joint that closes a loop is a
 * constraint. Nothing of the harness is used. */
#include <Simbody.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>

#include "oracle_model.h"

using namespace SimTK;

namespace {

Rotation marker_rotation(const oracle::Orientation &o)
{
    switch (o.form) {
    case oracle::Orientation::EULER313:
        return Rotation(o.angle[0], ZAxis) * Rotation(o.angle[1], XAxis) * Rotation(o.angle[2], ZAxis);
    case oracle::Orientation::COSINES: {
        Mat33 r;
        for (int k = 0; k < 3; ++k)
            r(k, 0) = o.x[k], r(k, 1) = o.y[k], r(k, 2) = o.z[k];
        return Rotation(r, true);
    }
    default:
        return Rotation();
    }
}

struct Built {
    MultibodySystem system;
    SimbodyMatterSubsystem matter{system};
    GeneralForceSubsystem forces{system};
    std::map<int, MobilizedBody> body_of;      /* body id -> its mobilized body */
    std::map<int, MobilizedBody> mobilizer_of; /* tree joint id -> the child's */
    std::map<int, Transform> frame0;           /* body id -> its frame at t = 0 */
};

void fail(const std::string &what) { throw std::runtime_error(what); }

Rotation from_columns(const Vec3 &x, const Vec3 &y, const Vec3 &z)
{
    Mat33 r;
    for (int k = 0; k < 3; ++k)
        r(k, 0) = x[k], r(k, 1) = y[k], r(k, 2) = z[k];
    return Rotation(r, true);
}

const oracle::Marker &find_marker(const oracle::Model &m, int id)
{
    for (const oracle::Marker &k : m.markers)
        if (k.id == id)
            return k;
    fail("no marker " + std::to_string(id));
    return m.markers[0];
}

Transform marker_frame(const oracle::Marker &k)
{
    return Transform(marker_rotation(k.orientation), Vec3(k.pos[0], k.pos[1], k.pos[2]));
}

/* The joint frame W at t = 0 (world), in which F and M coincide; parent_is_j
 * says which marker is on the tree's parent. Each type checks that its
 * markers satisfy the joint at t = 0, as the model's initial state must. */
Transform joint_frame(const oracle::Joint &j, const Transform &I, const Transform &J, bool parent_is_j)
{
    const Vec3 zI = I.R().z(), zJ = J.R().z();
    const double gap = (I.p() - J.p()).norm();
    if (j.type == "REVOLUTE" || j.type == "CYLINDRICAL") {
        if (gap > 1e-15 || (zI - zJ).norm() > 1e-15)
            fail("joint " + std::to_string(j.id) + ": I and J markers must coincide, z axes aligned");
        return J;
    }
    if (j.type == "SPHERICAL") {
        if (gap > 1e-15)
            fail("joint " + std::to_string(j.id) + ": I and J origins must coincide");
        return J;
    }
    if (j.type == "UNIVERSAL") { /* the pins: z_J on J's body, z_I on I's; Simbody's
                                    universal turns about F's x, then M's y */
        if (gap > 1e-15 || std::fabs(dot(zI, zJ)) > 1e-15)
            fail("joint " + std::to_string(j.id) + ": origins must coincide, z axes perpendicular");
        const Vec3 x = parent_is_j ? zJ : zI, y = parent_is_j ? zI : zJ;
        return Transform(from_columns(x, y, cross(x, y)), J.p());
    }
    if (j.type == "TRANSLATIONAL") { /* Simbody's slider moves along F's x */
        if (gap > 1e-15 || (I.R().asMat33() - J.R().asMat33()).norm() > 1e-15)
            fail("joint " + std::to_string(j.id) + ": I and J markers must coincide");
        return Transform(from_columns(zJ, J.R().x(), J.R().y()), J.p());
    }
    fail("joint " + std::to_string(j.id) + ": type " + j.type + " is not built by the oracle");
    return J;
}

MobilizedBody add_mobilizer(const std::string &type, MobilizedBody &parent,
                            const Transform &X_PF, const Body::Rigid &body, const Transform &X_BM)
{
    if (type == "REVOLUTE")
        return MobilizedBody::Pin(parent, X_PF, body, X_BM);
    if (type == "SPHERICAL")
        return MobilizedBody::Ball(parent, X_PF, body, X_BM);
    if (type == "UNIVERSAL")
        return MobilizedBody::Universal(parent, X_PF, body, X_BM);
    if (type == "CYLINDRICAL")
        return MobilizedBody::Cylinder(parent, X_PF, body, X_BM);
    if (type == "TRANSLATIONAL")
        return MobilizedBody::Slider(parent, X_PF, body, X_BM);
    fail("no mobilizer for " + type);
    return parent;
}

/* Grows the tree from ground in the joints' order; a joint between two bodies
 * already in it becomes a loop constraint. */
void build(Built &b, const oracle::Model &m)
{
    Force::UniformGravity(b.forces, b.matter, Vec3(m.gravity[0], m.gravity[1], m.gravity[2]));
    b.body_of[m.ground] = b.matter.Ground();
    b.frame0[m.ground] = Transform();
    std::map<int, const oracle::Body *> bodies;
    for (const oracle::Body &body : m.bodies) {
        bodies[body.id] = &body;
        b.frame0[body.id] = marker_frame(find_marker(m, body.cg_marker));
    }
    for (const oracle::Joint &j : m.joints) {
        const oracle::Marker &mi = find_marker(m, j.i_marker), &mj = find_marker(m, j.j_marker);
        const bool has_i = b.body_of.count(mi.body) != 0, has_j = b.body_of.count(mj.body) != 0;
        const Transform I = marker_frame(mi), J = marker_frame(mj);
        if (has_i && has_j) {
            if (j.type != "SPHERICAL")
                fail("joint " + std::to_string(j.id) + ": only a SPHERICAL joint closes a loop here");
            const Transform &Xi = b.frame0[mi.body], &Xj = b.frame0[mj.body];
            Constraint::Ball(b.body_of[mi.body], ~Xi * I.p(), b.body_of[mj.body], ~Xj * J.p());
            continue;
        }
        if (!has_i && !has_j)
            fail("joint " + std::to_string(j.id) + ": neither body is in the tree yet");
        const int parent = has_j ? mj.body : mi.body, child = has_j ? mi.body : mj.body;
        const oracle::Body &c = *bodies.at(child);
        /* Simbody's products are the tensor's entries: the negatives of the
         * Adams-style integrals the XML gives */
        const Body::Rigid info(MassProperties(c.mass, Vec3(0),
                                              Inertia(c.ixx, c.iyy, c.izz, -c.ixy, -c.ixz, -c.iyz)));
        const Transform W = joint_frame(j, I, J, has_j);
        MobilizedBody mob = add_mobilizer(j.type, b.body_of[parent], ~b.frame0[parent] * W, info,
                                          ~b.frame0[child] * W);
        b.body_of[child] = mob;
        b.mobilizer_of[j.id] = mob;
    }
    for (const oracle::Body &body : m.bodies)
        if (b.body_of.count(body.id) == 0)
            fail("body " + std::to_string(body.id) + " is on no joint");
}

/* The state at t = 0: every q zero (F on M), the tree joints' speeds, and with
 * a loop, the others projected onto its velocity constraint while the driver
 * joint's speed is held. */
State initial_state(Built &b, const oracle::Model &m)
{
    State s = b.system.realizeTopology();
    b.system.realizeModel(s);
    for (const oracle::Joint &j : m.joints) {
        if (b.mobilizer_of.count(j.id) == 0)
            continue;
        const MobilizedBody &mob = b.mobilizer_of[j.id];
        if ((int)j.speeds.size() != mob.getNumU(s))
            fail("joint " + std::to_string(j.id) + ": " + std::to_string(mob.getNumU(s)) + " speeds expected");
        if (j.type == "SPHERICAL")
            mob.setUToFitAngularVelocity(s, Vec3(j.speeds[0], j.speeds[1], j.speeds[2]));
        else
            for (int k = 0; k < mob.getNumU(s); ++k)
                mob.setOneU(s, k, j.speeds[k]);
    }
    if (m.driver_joint != 0) {
        const MobilizedBody &driver = b.mobilizer_of.at(m.driver_joint);
        driver.lock(s, Motion::Velocity);
        b.system.realize(s, Stage::Position);
        b.system.projectU(s, 1e-14);
        driver.unlock(s);
    }
    b.system.realize(s, Stage::Velocity);
    if (b.matter.getUErr(s).normInf() > 1e-13 || b.matter.getQErr(s).normInf() > 1e-13)
        fail("the initial state does not satisfy the constraints");
    return s;
}

void write_header(FILE *f, const oracle::Model &m)
{
    std::fprintf(f, "t");
    for (const oracle::Body &body : m.bodies) {
        const int id = body.id;
        std::fprintf(f, ",body%d.x,body%d.y,body%d.z,body%d.q0,body%d.q1,body%d.q2,body%d.q3"
                        ",body%d.vx,body%d.vy,body%d.vz,body%d.wx,body%d.wy,body%d.wz",
                     id, id, id, id, id, id, id, id, id, id, id, id, id);
    }
    std::fprintf(f, "\n");
}

/* One row; each body's quaternion keeps the sign of its previous row's. */
void write_row(FILE *f, const Built &b, const oracle::Model &m, const State &s, std::map<int, Vec4> &last_q)
{
    std::fprintf(f, "%.17g", s.getTime());
    for (const oracle::Body &body : m.bodies) {
        const MobilizedBody &mob = b.body_of.at(body.id);
        const Vec3 p = mob.getBodyOriginLocation(s), v = mob.getBodyOriginVelocity(s);
        const Vec3 w = mob.getBodyAngularVelocity(s);
        Vec4 q = mob.getBodyRotation(s).convertRotationToQuaternion().asVec4();
        if (last_q.count(body.id) != 0 && dot(q, last_q[body.id]) < 0)
            q = -q;
        last_q[body.id] = q;
        std::fprintf(f, ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g",
                     p[0], p[1], p[2], q[0], q[1], q[2], q[3], v[0], v[1], v[2], w[0], w[1], w[2]);
    }
    std::fprintf(f, "\n");
}

int usage()
{
    std::fprintf(stderr, "usage: simbody_oracle NAME --out FILE.csv [--end T] [--interval DT] [--accuracy A] [--time]\n"
                         "       simbody_oracle NAME --initial\n"
                         "       simbody_oracle --list\n"
                         "NAME: one of --list, or chain --bodies N (1 <= N <= 1024)\n");
    return 2;
}

}  // namespace

int main(int argc, char **argv)
{
    if (argc == 2 && std::string(argv[1]) == "--list") {
        for (const std::string &name : oracle::model_names())
            std::printf("%s\n", name.c_str());
        return 0;
    }
    if (argc < 3)
        return usage();
    const char *out = nullptr;
    bool initial = false, timed = false;
    double end = 1.0, interval = 0.01, accuracy = 1e-12;
    int chain_bodies = 0;
    for (int k = 2; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--initial")
            initial = true;
        else if (a == "--time")
            timed = true;
        else if (k + 1 < argc && a == "--out")
            out = argv[++k];
        else if (k + 1 < argc && a == "--end")
            end = std::atof(argv[++k]);
        else if (k + 1 < argc && a == "--interval")
            interval = std::atof(argv[++k]);
        else if (k + 1 < argc && a == "--accuracy")
            accuracy = std::atof(argv[++k]);
        else if (k + 1 < argc && a == "--bodies")
            chain_bodies = std::atoi(argv[++k]);
        else
            return usage();
    }
    oracle::Model chain;
    const oracle::Model *m = nullptr;
    if (std::string(argv[1]) == "chain") {
        if (chain_bodies < 1 || chain_bodies > 1024) {
            std::fprintf(stderr, "simbody_oracle: chain needs --bodies N, 1 <= N <= 1024\n");
            return 2;
        }
        chain = oracle::chain(chain_bodies);
        m = &chain;
    } else if (chain_bodies != 0) {
        std::fprintf(stderr, "simbody_oracle: --bodies is for the chain only\n");
        return 2;
    } else if ((m = oracle::find_model(argv[1])) == nullptr) {
        std::fprintf(stderr, "simbody_oracle: no model '%s' (--list names them)\n", argv[1]);
        return 2;
    }
    if (!initial && (out == nullptr || !(end > 0) || !(interval > 0) || !(accuracy > 0)))
        return usage();
    try {
        Built b;
        build(b, *m);
        State s = initial_state(b, *m);
        if (initial) { /* the XML's initial velocities: world axes, at each centre of mass */
            for (const oracle::Body &body : m->bodies) {
                const MobilizedBody &mob = b.body_of.at(body.id);
                const Vec3 v = mob.getBodyOriginVelocity(s), w = mob.getBodyAngularVelocity(s);
                std::printf("body %d: v_ic_x=\"%.17g\" v_ic_y=\"%.17g\" v_ic_z=\"%.17g\""
                            " w_ic_x=\"%.17g\" w_ic_y=\"%.17g\" w_ic_z=\"%.17g\"\n",
                            body.id, v[0], v[1], v[2], w[0], w[1], w[2]);
            }
            return 0;
        }
        RungeKuttaMersonIntegrator integ(b.system);
        integ.setAccuracy(accuracy);
        integ.setConstraintTolerance(accuracy);
        integ.setAllowInterpolation(false); /* every row a step's end, not an interpolant */
        integ.initialize(s);
        FILE *f = std::fopen(out, "w");
        if (f == nullptr) {
            std::fprintf(stderr, "simbody_oracle: cannot write %s\n", out);
            return 1;
        }
        std::map<int, Vec4> last_q;
        write_header(f, *m);
        const double energy0 = b.system.calcEnergy(integ.getState());
        write_row(f, b, *m, integ.getState(), last_q);
        const int rows = (int)std::lround(end / interval);
        double worst_qerr = 0, stepping = 0;
        for (int k = 1; k <= rows; ++k) {
            const double t = k * interval;
            while (integ.getTime() < t) {
                const auto start = std::chrono::steady_clock::now();
                const Integrator::SuccessfulStepStatus status = integ.stepTo(t);
                stepping += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (status == Integrator::EndOfSimulation)
                    fail("the integrator ended the simulation at t = " + std::to_string(integ.getTime()));
            }
            const State &st = integ.getState();
            b.system.realize(st, Stage::Velocity);
            worst_qerr = std::max(worst_qerr, b.matter.getQErr(st).normInf());
            write_row(f, b, *m, st, last_q);
        }
        const double energy1 = b.system.calcEnergy(integ.getState());
        std::fclose(f);
        std::printf("simbody_oracle %s: %d rows to t = %g, %d steps, accuracy %g; energy %.12g J, change %.3g J;"
                    " largest loop residual %.3g m\n",
                    m->name.c_str(), rows + 1, end, integ.getNumStepsTaken(), accuracy, energy0,
                    energy1 - energy0, worst_qerr);
        if (timed) /* one line, its words fixed: scripts/oracle_speed.sh reads it */
            std::printf("simbody_oracle time: integration %.6f s, realizations %d, steps %d, attempted %d,"
                        " projections %d, %.4g us per realization\n",
                        stepping, integ.getNumRealizations(), integ.getNumStepsTaken(),
                        integ.getNumStepsAttempted(), integ.getNumProjections(),
                        integ.getNumRealizations() ? 1e6 * stepping / integ.getNumRealizations() : 0.0);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "simbody_oracle %s: %s\n", m->name.c_str(), e.what());
        return 1;
    }
    return 0;
}
