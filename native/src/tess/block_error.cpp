#include "tess/block_error.h"

namespace trimkit::tess {

BlockError block_error(const SecondDerivativeBound& M, double du, double dv) {
    BlockError e;
    e.u_term = M.M_uu * du * du / 8.0;
    e.v_term = M.M_vv * dv * dv / 8.0;
    e.bound = e.u_term + M.M_uv * du * dv / 4.0 + e.v_term;
    return e;
}

SecondDerivativeBound in_surface_parameters(const SecondDerivativeBound& local, double du, double dv) {
    return {local.M_uu / (du * du), local.M_uv / (du * dv), local.M_vv / (dv * dv)};
}

}  // namespace trimkit::tess
