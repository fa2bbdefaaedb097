/* The oracle's description of a mechanism: the same numbers as one of the XML
 * models beside this file (bodies, markers, joints, gravity, initial speeds),
 * written a second time in C++ so that Simbody, not the harness's reader,
 * builds it (docs/testing.md, "The Simbody oracle"). */
#ifndef ORACLE_MODEL_H
#define ORACLE_MODEL_H

#include <string>
#include <vector>

namespace oracle {

/* A marker's orientation, as the XML gives it: 3-1-3 Euler angles (psi,
 * theta, phi; R = Rz(psi) Rx(theta) Rz(phi)) or direction cosines (the
 * columns are the marker's x, y and z axes in world). Neither: the world's. */
struct Orientation {
    enum Form { WORLD, EULER313, COSINES } form = WORLD;
    double angle[3] = {0, 0, 0};
    double x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
};

struct Marker {
    int id;
    int body;       /* the body's id */
    double pos[3];  /* world, at t = 0 */
    Orientation orientation;
};

/* A moving body: its frame is its centre-of-mass marker's; the inertia is
 * about that marker, in its axes, with the products as the XML gives them
 * (the Adams convention: inertia_xy = +integral of x y dm). */
struct Body {
    int id;
    int cg_marker;
    double mass;
    double ixx, iyy, izz, ixy, iyz, ixz;
};

/* A joint by its MotionSolve type, with the speeds of its Simbody mobilizer
 * at t = 0 (tree joints only; see oracle_models.cpp for what each means). */
struct Joint {
    int id;
    std::string type;  /* REVOLUTE, SPHERICAL, UNIVERSAL, CYLINDRICAL, TRANSLATIONAL */
    int i_marker, j_marker;
    std::vector<double> speeds;
};

struct Model {
    std::string name;
    int ground;  /* the ground body's id */
    double gravity[3];
    std::vector<Body> bodies;
    std::vector<Marker> markers;
    /* in the order the tree is grown from ground: a joint whose two bodies
     * are already in the tree closes a loop (SPHERICAL only) */
    std::vector<Joint> joints;
    /* a loop's driver: the joint whose speed is held while the others are
     * projected onto the loop's velocity constraint (0: no loop) */
    int driver_joint;
};

/* The models, by name (oracle_models.cpp); a null pointer for an unknown name. */
const Model *find_model(const std::string &name);
std::vector<std::string> model_names();

/* The chain of n bars on SPHERICAL joints that scripts/joint_chain_model.sh n
 * writes (docs/performance.md, "Joints between bodies"): the same ids, masses,
 * inertias and marker positions, so that the harness runs that script's XML
 * and Simbody this. */
Model chain(int n);

}  // namespace oracle

#endif
