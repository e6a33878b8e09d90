// The relations of laws/ in the time loop (asterlite.dynamics.laws.kernel):
// the generalized forces of every row of the shocks whose F_LAW is not DIS_CHOC.
#pragma once

#include <cstdint>

#include "contact.hpp"
#include "views.hpp"

namespace asterlite {
namespace laws {

// the branch of each relation (laws.kernel)
enum Code : std::int64_t {
    DIS_CHOC, FLAMBAGE, ANTI_SISM, DIS_VISC, DIS_ECRO_TRAC,
    CHOC_ELAS_TRAC, RELA_EFFO_DEPL, RELA_EFFO_VITE, ROTOR_FISS,
};
constexpr std::int64_t LAST_CODE = ROTOR_FISS;
constexpr index N_WORK = 9;  // laws.rk54.N_WORK
constexpr index W_RATE = N_WORK, W_KIN = W_RATE + 1, W_VECTOR = W_KIN + 6;
constexpr index SCRATCH_ROWS = W_VECTOR + 3, SCRATCH_COLS = 14;

}  // namespace laws

// laws.kernel.law_forces: add the generalized forces of every non-DIS_CHOC row to out
// (shk.law_scratch: its work); -1
inline index law_forces(double, const F1&, const F1&, const Shocks&, const F2&, const F1&) {
    return -1;  // PLACEHOLDER until the port lands: native.LAWS_PORTED keeps laws on numba
}

}  // namespace asterlite
