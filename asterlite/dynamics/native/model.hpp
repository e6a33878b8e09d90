// The bundles every loop receives (asterlite.dynamics.layouts): the linear
// system, the shocks, the loads and support motions, the shocks' local
// frames, the state, a scheme's memory.
#pragma once

#include "contact.hpp"
#include "loads.hpp"
#include "views.hpp"

namespace asterlite {

// model.LinearSystem.bundle(): (n, n) M^-1, K, C and whether all are diagonal
struct Linear {
    F2 minv, stiffness, damping;
    bool diagonal = false;
};

// the 4th bundle of the loops in local frames (integrate.local_frame_bundle)
struct Local {
    F4 shapes;  // (n_shocks, 2, 3, n_modes): rot Phi
    F3 rest;    // (n_shocks, 2, 3): rot (coord - origin)
    F3 drive;   // (n_shocks, 2, 6): support motion in the local frames
};

// local_frames: the model of a scheme's own loop (the 4th bundle: its steps
// evaluate in local frames, local_frame.py); else the general model (the
// three bundles of the general paths: global frame, relations of laws/)
struct Model {
    Linear lin;
    Shocks shk;
    Loads loads;
    Supports sup;
    Local local;
    bool local_frames = true;
};

// layouts.State: q, v, a, the force f, the shocks' internal variables and
// their copy before a trial, a (5, 3) scratch
struct State {
    F1 q, v, a, f;
    F2 vint, vint_save, work;
};

// a scheme's memory: rows of length n, scalars, a coefficient table
struct Memory {
    F2 rows;
    F1 scalars;
    F2 table;
};

}  // namespace asterlite
