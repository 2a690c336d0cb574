#include "tether/elements/mean_dilatation.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>

#include "tether/core/error.hpp"

namespace tether {

VolumePoint volume_point(const PointShape& p, const double* ue) {
  const int n = static_cast<int>(p.N.size());
  VolumePoint v;
  double ur = 0;
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 2; ++i) {
      v.F(i, 0) += ue[2 * a + i] * p.G(a, 0);
      v.F(i, 1) += ue[2 * a + i] * p.G(a, 1);
    }
    ur += ue[2 * a] * p.N(a);
  }
  v.F33 = p.axisymmetric ? 1 + ur / p.R : 1.0;
  v.J = v.F.determinant() * v.F33;
  if (!(v.J > 0) || !(v.F33 > 0))
    throw ModelError(fmt::format("the deformation gradient is not invertible (J = {:.3g}, F33 = {:.3g}): the "
                                 "element is inverted",
                                 v.J, v.F33));
  const Eigen::Matrix2d FinvT = v.F.inverse().transpose();
  v.dlnJ.setZero(2 * n);
  for (int a = 0; a < n; ++a) {
    v.dlnJ.segment<2>(2 * a) = FinvT * p.G.row(a).transpose();  // d ln det F = F^-T : dF
    if (p.axisymmetric) v.dlnJ(2 * a) += p.N(a) / (p.R * v.F33);
  }
  return v;
}

void add_log_volume_hessian(const PointShape& p, const VolumePoint& v, double w, ElementMatrix& out) {
  // d^2 ln det F [dF1, dF2] = -tr(F^-1 dF1 F^-1 dF2); dF = du_a G_a^T.
  const int n = static_cast<int>(p.N.size());
  const Eigen::Matrix2d FinvT = v.F.inverse().transpose();
  ShapeGradient f(n, 2);  // row a: (F^-T G_a)^T
  for (int a = 0; a < n; ++a) f.row(a) = (FinvT * p.G.row(a).transpose()).transpose();
  const double hoop = p.axisymmetric ? 1 / (p.R * v.F33) : 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      for (int i = 0; i < 2; ++i)
        for (int k = 0; k < 2; ++k) out(2 * a + i, 2 * b + k) -= w * f(b, i) * f(a, k);
      out(2 * a, 2 * b) -= w * (hoop * p.N(a)) * (hoop * p.N(b));
    }
}

ElementVector volumetric_row(const PointShape& p) {
  const int n = static_cast<int>(p.N.size());
  ElementVector b(2 * n);
  for (int a = 0; a < n; ++a) {
    b(2 * a) = p.G(a, 0) + (p.axisymmetric ? p.N(a) / p.R : 0.0);
    b(2 * a + 1) = p.G(a, 1);
  }
  return b;
}

Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, kMaxElementDofs> strain_rows(const PointShape& p,
                                                                            const Eigen::Matrix2d& F, double F33) {
  const int n = static_cast<int>(p.N.size());
  Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, kMaxElementDofs> B(4, 2 * n);
  const double f33_over_r = p.axisymmetric ? F33 / p.R : 0.0;
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 2; ++i) {
      B(0, 2 * a + i) = F(i, 0) * p.G(a, 0);
      B(1, 2 * a + i) = F(i, 1) * p.G(a, 1);
      B(3, 2 * a + i) = F(i, 0) * p.G(a, 1) + F(i, 1) * p.G(a, 0);
    }
    B(2, 2 * a) = f33_over_r * p.N(a);
    B(2, 2 * a + 1) = 0;
  }
  return B;
}

void add_geometric_stiffness(const PointShape& p, const Eigen::Vector4d& S, ElementMatrix& out) {
  const int n = static_cast<int>(p.N.size());
  for (int a = 0; a < n; ++a) {
    const double sa0 = S(0) * p.G(a, 0) + S(3) * p.G(a, 1);
    const double sa1 = S(3) * p.G(a, 0) + S(1) * p.G(a, 1);
    const double hoop_a = p.axisymmetric ? S(2) * p.N(a) / (p.R * p.R) : 0.0;
    for (int b = 0; b < n; ++b) {
      const double g = sa0 * p.G(b, 0) + sa1 * p.G(b, 1);
      out(2 * a, 2 * b) += g + hoop_a * p.N(b);
      out(2 * a + 1, 2 * b + 1) += g;
    }
  }
}

double dilatation_scale(double theta, double J) { return std::cbrt(theta / J); }

Eigen::Matrix<double, 6, 1> mean_dilatation_strain(const Eigen::Matrix<double, 6, 1>& strain, double e_bar) {
  Eigen::Matrix<double, 6, 1> out = strain;
  const double shift = (e_bar - (strain(0) + strain(1) + strain(2))) / 3;
  for (int i = 0; i < 3; ++i) out(i) += shift;
  return out;
}

}  // namespace tether
