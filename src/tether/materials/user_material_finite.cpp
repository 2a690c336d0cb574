/// \file UserMaterial under NLGEOM: the routine called in the polar-rotated
/// frame with a Hughes-Winget increment (docs/theory/user_material.md).
#include <Eigen/LU>
#include <cmath>

#include "tether/core/error.hpp"
#include "tether/materials/user_material.hpp"

namespace tether {

namespace {

using M3 = Eigen::Matrix3d;

/// The right stretch U = sqrt(C) of a C with C13 = C23 = 0 (2D), in closed
/// form: the in-plane block (C2 + s I) / t with s = sqrt(det C2), t =
/// sqrt(tr C2 + 2 s); U33 = sqrt(C33).
struct RightStretch {
  M3 U = M3::Zero();
  double s = 0, t = 0;

  explicit RightStretch(const M3& C) {
    const Eigen::Matrix2d C2 = C.topLeftCorner<2, 2>();
    s = std::sqrt(C2.determinant());
    t = std::sqrt(C2.trace() + 2 * s);
    U.topLeftCorner<2, 2>() = (C2 + s * Eigen::Matrix2d::Identity()) / t;
    U(2, 2) = std::sqrt(C(2, 2));
  }

  /// dU for a change dC of C (same block structure).
  [[nodiscard]] M3 derivative(const M3& C, const M3& dC) const {
    const Eigen::Matrix2d C2 = C.topLeftCorner<2, 2>(), dC2 = dC.topLeftCorner<2, 2>();
    const double ds = 0.5 * s * (C2.inverse() * dC2).trace(), dt = (dC2.trace() + 2 * ds) / (2 * t);
    M3 dU = M3::Zero();
    dU.topLeftCorner<2, 2>() = (dC2 + ds * Eigen::Matrix2d::Identity() - U.topLeftCorner<2, 2>() * dt) / t;
    dU(2, 2) = dC(2, 2) / (2 * U(2, 2));
    return dU;
  }
};

/// Symmetric tensor of ABAQUS components (11, 22, 33, 12); `shear`: the
/// factor of the 12 entry (1 for stress, 1/2 for engineering strain).
M3 tensor_of(const double* v, double shear) {
  M3 t = M3::Zero();
  t(0, 0) = v[0], t(1, 1) = v[1], t(2, 2) = v[2];
  t(0, 1) = t(1, 0) = shear * v[3];
  return t;
}

/// ABAQUS components (11, 22, 33, 12) of a symmetric tensor; `shear` as above, inverted.
void components_of(const M3& t, double shear, double* v) {
  v[0] = t(0, 0), v[1] = t(1, 1), v[2] = t(2, 2), v[3] = t(0, 1) / shear;
}

Vec6 voigt_of(const M3& t, double shear) {
  Vec6 v = Vec6::Zero();
  double c[4];
  components_of(t, shear, c);
  v << c[0], c[1], c[2], c[3], 0, 0;
  return v;
}

/// The kinematics of one increment, from U0 to U1: A = (U1 - U0) Um^-1 with
/// Um = (U0 + U1) / 2, DSTRAN = sym A, the spin increment skew A and DROT =
/// (I - skew A / 2)^-1 (I + skew A / 2) (Hughes-Winget).
struct Increment {
  M3 um_inv, a, deps, m_inv, drot;

  Increment(const M3& U0, const M3& U1) {
    um_inv = (0.5 * (U0 + U1)).inverse();
    a = (U1 - U0) * um_inv;
    deps = 0.5 * (a + a.transpose());
    const M3 dw = 0.5 * (a - a.transpose());
    m_inv = (M3::Identity() - 0.5 * dw).inverse();
    drot = m_inv * (M3::Identity() + 0.5 * dw);
  }
};

}  // namespace

void UserMaterial::update_finite_strain(M3& C, bool plane_stress, std::span<const double> old_state,
                                        std::span<double> new_state, const PointContext& where,
                                        MaterialResponse& out) const {
  if (plane_stress)
    throw ModelError("user material " + name_ + ": plane stress (CPS) under NLGEOM is not supported for a user "
                     "material (tether does not know its thickness stretch): use CPE or CAX elements, or run the "
                     "step without NLGEOM");
  const M3 U0 = M3::Identity() + from_voigt_stress(Eigen::Map<const Vec6>(old_state.data() + 15));
  const RightStretch stretch(C);
  const M3& U1 = stretch.U;
  const Increment inc(U0, U1);
  const M3 sigma0 = from_voigt_stress(Eigen::Map<const Vec6>(old_state.data()));
  const M3 Q = inc.drot, sigma_in = Q * sigma0 * Q.transpose();
  M3 strain0 = M3::Zero();
  {
    const Eigen::Map<const Vec6> e(old_state.data() + 6);
    const double v[4] = {e(0), e(1), e(2), e(3)};
    strain0 = tensor_of(v, 0.5);
  }
  const M3 stran_in = Q * strain0 * Q.transpose();
  UmatCall c;
  c.ntens = 4;
  components_of(sigma_in, 1, c.stress);
  components_of(stran_in, 0.5, c.stran);
  components_of(inc.deps, 0.5, c.dstran);
  Eigen::Map<M3>(c.drot.data()) = Q;
  Eigen::Map<M3>(c.dfgrd0.data()) = U0;
  Eigen::Map<M3>(c.dfgrd1.data()) = U1;
  call_routine(c, old_state, new_state, where);

  const M3 sigma1 = tensor_of(c.stress, 1), u_inv = U1.inverse();
  const double J = U1.determinant();
  const M3 S = J * u_inv * sigma1 * u_inv;
  const Eigen::Map<const Eigen::Matrix4d> ddsdde(c.ddsdde);
  out.stress = voigt_of(S, 1);
  out.tangent.setZero();
  for (int k = 0; k < 4; ++k) {  // dS along dE = e_k (engineering shear): dC = 2 dE
    M3 dC = M3::Zero();
    if (k < 3) dC(k, k) = 2;
    else dC(0, 1) = dC(1, 0) = 1;
    const M3 dU = stretch.derivative(C, dC);
    const M3 dA = (M3::Identity() - 0.5 * inc.a) * dU * inc.um_inv;
    const M3 d_deps = 0.5 * (dA + dA.transpose()), d_dw = 0.5 * (dA - dA.transpose());
    const M3 dQ = inc.m_inv * (0.5 * d_dw) * (Q + M3::Identity());
    Eigen::Vector4d de, ds;
    components_of(d_deps, 0.5, de.data());
    ds.noalias() = ddsdde * de;
    const M3 d_sigma = dQ * sigma0 * Q.transpose() + Q * sigma0 * dQ.transpose() + tensor_of(ds.data(), 1);
    const M3 du_inv = -u_inv * dU * u_inv;
    const double dJ = J * (u_inv * dU).trace();
    const M3 dS = (dJ / J) * S + J * (du_inv * sigma1 * u_inv + u_inv * sigma1 * du_inv + u_inv * d_sigma * u_inv);
    out.tangent.col(k) = voigt_of(dS, 1);
  }
  out.elastic_energy = c.sse;
  out.dissipation = c.spd - old_state[13];
  Eigen::Map<Vec6>(new_state.data()) = voigt_of(sigma1, 1);
  Eigen::Map<Vec6>(new_state.data() + 6) = voigt_of(stran_in + inc.deps, 0.5);
  Eigen::Map<Vec6>(new_state.data() + 15) = voigt_of(U1 - M3::Identity(), 1);
}

}  // namespace tether
