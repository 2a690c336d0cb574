// Mortar kinematics: the dual basis, projection along the slave normal
// field, segmentation and the integrals D and M against hand calculations,
// their consistency (Σ D = overlapped area, M row sums = D) and the exact
// derivatives (Dual2) against central finite differences.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <stdexcept>

#include "tether/contact/mortar_segmentation.hpp"

using namespace tether;

namespace {

using V = Vec2T<double>;

std::vector<V> flat_normals(int n, V normal) { return std::vector<V>(static_cast<std::size_t>(n), normal); }

TEST(MortarDualBasis, StraightLinearSegmentHasTheTextbookCoefficients) {
  const std::vector<V> x{{0, 0}, {2, 0}};
  const auto A = dual_coefficients<double>(x);
  EXPECT_NEAR(A[0][0], 2, 1e-14);
  EXPECT_NEAR(A[0][1], -1, 1e-14);
  EXPECT_NEAR(A[1][0], -1, 1e-14);
  EXPECT_NEAR(A[1][1], 2, 1e-14);
}

TEST(MortarDualBasis, CurvedQuadraticSegmentIsBiorthogonalWithPositiveWeights) {
  const std::vector<V> x{{0, 0}, {2, 0.1}, {1.1, 0.3}};  // corners, then mid-side node
  const auto A = dual_coefficients<double>(x);
  // ∫ Φ_k N_l ds = δ_kl ∫ N_k ds, checked with a finer rule than the one used.
  double D[3][3] = {}, area[3] = {};
  const int n = 40;
  for (int i = 0; i < n; ++i) {
    const double s0 = -1 + 2.0 * i / n, s1 = s0 + 2.0 / n;
    for (double g : {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)}) {
      const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * g;
      std::array<double, 3> N, dN;
      segment_shapes(3, s, N, dN);
      V dx{0, 0};
      for (int a = 0; a < 3; ++a) dx = dx + dN[static_cast<std::size_t>(a)] * x[static_cast<std::size_t>(a)];
      const double w = 0.5 * (s1 - s0) * std::sqrt(dot(dx, dx));
      for (int k = 0; k < 3; ++k) {
        double phi = 0;
        for (int l = 0; l < 3; ++l) phi += A[k][l] * N[static_cast<std::size_t>(l)];
        area[k] += w * N[static_cast<std::size_t>(k)];
        for (int l = 0; l < 3; ++l) D[k][l] += w * phi * N[static_cast<std::size_t>(l)];
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(area[k], 0) << k;
    for (int l = 0; l < 3; ++l) EXPECT_NEAR(D[k][l], k == l ? area[k] : 0.0, 1e-6) << k << "," << l;
  }
}

TEST(MortarSegmentation, PartialOverlapMatchesHandCalculation) {
  // Slave segment (0,0)-(2,0) (bottom face of a body above: outward normal
  // (0,-1)); master face (3,-0.1)-(1,-0.1) below it (the top face of a body
  // below, run the other way): overlap x in [1, 2], i.e. ξ in [0, 1];
  // η = 1 - ξ. With Φ1 = 1/2 - 3ξ/2, Φ2 = 1/2 + 3ξ/2 and ds = dξ:
  //   D1 = ∫0^1 Φ1 = -1/4, D2 = 5/4;  M11 = M12 = -1/8, M21 = 3/8, M22 = 7/8.
  const std::vector<V> x{{0, 0}, {2, 0}};
  const std::vector<V> normals = flat_normals(2, {0, -1});
  const std::vector<std::vector<V>> masters{{{3, -0.1}, {1, -0.1}}};
  const SegmentMortar<double> m = integrate_segment<double>(x, normals, masters, 1.0);
  EXPECT_NEAR(m.overlap[0][0], 0, 1e-14);
  EXPECT_NEAR(m.overlap[0][1], 1, 1e-14);
  EXPECT_NEAR(m.D[0], -0.25, 1e-14);
  EXPECT_NEAR(m.D[1], 1.25, 1e-14);
  EXPECT_NEAR(m.M[0][0][0], -0.125, 1e-14);
  EXPECT_NEAR(m.M[0][0][1], -0.125, 1e-14);
  EXPECT_NEAR(m.M[0][1][0], 0.375, 1e-14);
  EXPECT_NEAR(m.M[0][1][1], 0.875, 1e-14);
  // Weighted gap of node 2: n·(Σ M y - D x) = D2 × 0.1 (the gap is uniform).
  const double g = -(m.M[0][1][0] * -0.1 + m.M[0][1][1] * -0.1 - m.D[1] * 0.0);
  EXPECT_NEAR(g, 0.125, 1e-14);
}

TEST(MortarSegmentation, FullCoverageSumsToTheSegmentAreaAndMRowsToD) {
  // A slave segment covered by three master segments of a finer, slightly
  // inclined and offset mesh; thickness 0.5. Σ_k D_k = length × thickness
  // and Σ_f Σ_a M[f][k][a] = D_k (the master shape functions sum to one).
  const std::vector<V> x{{0, 0}, {3, 0.6}};
  const double length = std::sqrt(9 + 0.36), t = 0.5;
  const V n{0.6 / length, -3 / length};
  const std::vector<V> normals = flat_normals(2, n);
  std::vector<std::vector<V>> masters;
  const std::vector<double> cuts{4.0, 2.2, 1.1, -0.7};  // x of the master nodes, right to left
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    masters.push_back({{cuts[i], 0.2 * cuts[i] - 0.05}, {cuts[i + 1], 0.2 * cuts[i + 1] - 0.05}});
  const SegmentMortar<double> m = integrate_segment<double>(x, normals, masters, t);
  EXPECT_NEAR(m.D[0] + m.D[1], length * t, 1e-13);
  EXPECT_NEAR(m.D[0], 0.5 * length * t, 1e-13);  // full coverage: D_kk = ∫ N_k dA
  for (int k = 0; k < 2; ++k) {
    double row = 0;
    for (const auto& mf : m.M) row += mf[static_cast<std::size_t>(k)][0] + mf[static_cast<std::size_t>(k)][1];
    EXPECT_NEAR(row, m.D[static_cast<std::size_t>(k)], 1e-13) << k;
  }
  // The pieces tile the segment: consecutive overlaps share their ends.
  EXPECT_NEAR(m.overlap[0][1], 1, 1e-14);
  EXPECT_NEAR(m.overlap[2][0], -1, 1e-14);
  EXPECT_NEAR(m.overlap[0][0], m.overlap[1][1], 1e-14);
  EXPECT_NEAR(m.overlap[1][0], m.overlap[2][1], 1e-14);
}

TEST(MortarSegmentation, MasterFacingTheOtherWayIsSkipped) {
  const std::vector<V> x{{0, 0}, {2, 0}};
  const std::vector<std::vector<V>> masters{{{0, -0.1}, {2, -0.1}}};  // same orientation as the slave
  const SegmentMortar<double> m = integrate_segment<double>(x, flat_normals(2, {0, -1}), masters, 1.0);
  EXPECT_GE(m.overlap[0][0], m.overlap[0][1]);
  EXPECT_EQ(m.D[0], 0.0);
  EXPECT_EQ(m.D[1], 0.0);
}

TEST(MortarSegmentation, ProjectionFollowsTheInterpolatedNormal) {
  const std::vector<V> x{{0, 0}, {2, 0.3}, {1.0, 0.25}};
  const std::vector<V> normals{{0.2, -0.98}, {-0.1, -0.995}, {0.05, -1}};
  const V p{1.3, -0.4};
  const std::optional<double> xi = project_along_slave_normals<double>(p, x, normals);
  ASSERT_TRUE(xi);
  std::array<double, 3> N, dN;
  segment_shapes(3, *xi, N, dN);
  V xs{0, 0}, n{0, 0};
  for (std::size_t a = 0; a < 3; ++a) xs = xs + N[a] * x[a], n = n + N[a] * normals[a];
  EXPECT_NEAR(cross(p - xs, n), 0.0, 1e-14);
  EXPECT_LT(dot(p - xs, n), 0.0 + 1.0) << "p lies along the normal ray";
}

/// A scalar summary of the mortar integrals of a curved quadratic slave
/// segment with varying nodal normals against two linear master segments
/// that cut it: Σ_k c_k D_k + Σ c_fka M[f][k][a], as a function of all
/// coordinates (slave 3 nodes, normals fixed, master 3 nodes).
template <class T>
T summary(const std::vector<T>& q) {
  auto p = [&](int i) { return Vec2T<T>{q[static_cast<std::size_t>(2 * i)], q[static_cast<std::size_t>(2 * i + 1)]}; };
  const std::vector<Vec2T<T>> x{p(0), p(1), p(2)};
  // Averaged nodal normals (the corner normals of the segment itself here).
  const std::vector<Vec2T<T>> seg{p(0), p(1), p(2)};
  const std::vector<std::vector<Vec2T<T>>> one{seg};
  const int at0 = 0, at1 = 1, at2 = 2;
  const std::vector<Vec2T<T>> normals{nodal_normal<T>(one, std::span(&at0, 1)), nodal_normal<T>(one, std::span(&at1, 1)),
                                      nodal_normal<T>(one, std::span(&at2, 1))};
  const std::vector<std::vector<Vec2T<T>>> masters{{p(3), p(4)}, {p(4), p(5)}};
  const SegmentMortar<T> m = integrate_segment<T>(x, normals, masters, 0.7);
  T s(0.0);
  for (int k = 0; k < 3; ++k) {
    s += (1.0 + 0.3 * k) * m.D[static_cast<std::size_t>(k)];
    for (int f = 0; f < 2; ++f)
      for (int a = 0; a < 2; ++a) s += (0.2 + 0.1 * k - 0.4 * f + 0.25 * a) * m.M[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)][static_cast<std::size_t>(a)];
  }
  return s;
}

TEST(MortarSegmentation, ExactDerivativesMatchFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const std::vector<double> base{0, 0, 2, 0.2, 1.0, 0.15, 2.6, -0.05, 1.3, -0.12, -0.5, -0.02};
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> q = base;
    for (double& v : q) v += jitter(rng);
    const int n = static_cast<int>(q.size());
    std::vector<Dual2> d;
    for (int i = 0; i < n; ++i) d.push_back(Dual2::variable(q[static_cast<std::size_t>(i)], i, n));
    const Dual2 s = summary<Dual2>(d);
    EXPECT_NEAR(s.value(), summary<double>(q), 1e-13);
    const double h = 1e-5;
    double grad_error = 0, hess_error = 0, scale = 1;
    for (int i = 0; i < n; ++i) {
      std::vector<double> qp = q, qm = q;
      qp[static_cast<std::size_t>(i)] += h;
      qm[static_cast<std::size_t>(i)] -= h;
      grad_error = std::max(grad_error, std::abs(s.gradient()[i] - (summary<double>(qp) - summary<double>(qm)) / (2 * h)));
      std::vector<Dual2> dp, dm;
      for (int k = 0; k < n; ++k) {
        dp.push_back(Dual2::variable(qp[static_cast<std::size_t>(k)], k, n));
        dm.push_back(Dual2::variable(qm[static_cast<std::size_t>(k)], k, n));
      }
      const Eigen::VectorXd fd = (summary<Dual2>(dp).gradient() - summary<Dual2>(dm).gradient()) / (2 * h);
      hess_error = std::max(hess_error, (s.hessian().col(i) - fd).cwiseAbs().maxCoeff());
      scale = std::max(scale, s.hessian().col(i).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(grad_error, 1e-8) << trial;
    EXPECT_LT(hess_error / scale, 1e-7) << trial;
    // Dual2 stores the lower triangle only: the Hessian is symmetric bit for bit.
    const Dual2::Hessian hs = s.hessian();
    EXPECT_TRUE(hs == hs.transpose()) << trial;
  }
}

/// A linear slave segment p1-p2 whose nodal normals are averaged with its
/// neighbours p0-p1 and p2-p3 (they differ from the segment's own normal
/// and from each other) against two linear master segments p4-p5, p5-p6
/// that cut it: Σ_k c_k D_k + Σ c_fka M[f][k][a] over all 14 coordinates.
/// `reference`: the integrals' measure from fixed reference positions (a
/// geometrically linear step), else the current one. The 2-node against
/// 2-node overlaps take integrate_segment's affine sums.
template <class T>
T linear_summary(const std::vector<T>& q, bool reference) {
  auto p = [&](int i) { return Vec2T<T>{q[static_cast<std::size_t>(2 * i)], q[static_cast<std::size_t>(2 * i + 1)]}; };
  const std::vector<Vec2T<T>> left{p(0), p(1)}, x{p(1), p(2)}, right{p(2), p(3)};
  const std::vector<std::vector<Vec2T<T>>> around1{left, x}, around2{x, right};
  const std::array<int, 2> at1{1, 0}, at2{1, 0};
  const std::vector<Vec2T<T>> normals{nodal_normal<T>(around1, at1), nodal_normal<T>(around2, at2)};
  const std::vector<std::vector<Vec2T<T>>> masters{{p(4), p(5)}, {p(5), p(6)}};
  const std::vector<V> measure = reference ? std::vector<V>{{0.02, -0.01}, {1.97, 0.22}} : std::vector<V>{};
  const SegmentMortar<T> m = integrate_segment<T>(x, normals, masters, 0.7, 6, measure);
  T s(0.0);
  for (int k = 0; k < 2; ++k) {
    s += (1.0 + 0.3 * k) * m.D[static_cast<std::size_t>(k)];
    for (int f = 0; f < 2; ++f)
      for (int a = 0; a < 2; ++a)
        s += (0.2 + 0.1 * k - 0.4 * f + 0.25 * a) * m.M[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)][static_cast<std::size_t>(a)];
  }
  return s;
}

TEST(MortarSegmentation, LinearSegmentsExactDerivativesMatchFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const std::vector<double> base{-1, -0.2, 0, 0, 2, 0.2, 3, 0.6, 2.6, -0.05, 1.3, -0.12, -0.5, -0.02};
  for (int trial = 0; trial < 6; ++trial) {
    const bool reference = trial % 2 == 1;
    std::vector<double> q = base;
    for (double& v : q) v += jitter(rng);
    const int n = static_cast<int>(q.size());
    const auto variables = [n](const std::vector<double>& at) {
      std::vector<Dual2> d;
      for (int i = 0; i < n; ++i) d.push_back(Dual2::variable(at[static_cast<std::size_t>(i)], i, n));
      return d;
    };
    const Dual2 s = linear_summary<Dual2>(variables(q), reference);
    EXPECT_NEAR(s.value(), linear_summary<double>(q, reference), 1e-13);
    const double h = 1e-5;
    double grad_error = 0, hess_error = 0, scale = 1;
    for (int i = 0; i < n; ++i) {
      std::vector<double> qp = q, qm = q;
      qp[static_cast<std::size_t>(i)] += h;
      qm[static_cast<std::size_t>(i)] -= h;
      grad_error = std::max(grad_error, std::abs(s.gradient()[i] - (linear_summary<double>(qp, reference) -
                                                                    linear_summary<double>(qm, reference)) / (2 * h)));
      const Eigen::VectorXd fd =
          (linear_summary<Dual2>(variables(qp), reference).gradient() - linear_summary<Dual2>(variables(qm), reference).gradient()) /
          (2 * h);
      hess_error = std::max(hess_error, (s.hessian().col(i) - fd).cwiseAbs().maxCoeff());
      scale = std::max(scale, s.hessian().col(i).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(grad_error, 1e-8) << trial;
    EXPECT_LT(hess_error / scale, 1e-7) << trial;
    // The Hessian is not trivially small: the normals and projections enter.
    EXPECT_GT(scale, 0.05) << trial;
  }
}

TEST(MortarSegmentation, LinearMasterSumsEqualTheGeneralQuadrature) {
  // The same straight master once as a 2-node segment (integrate_segment's
  // affine sums) and once as a 3-node one with its mid node at the middle
  // (the general Gauss-point loop): y(η) is the same map, so D and the
  // weighted gap vectors Σ_a M_ka y_a agree to round-off, and so do the
  // overlaps. Nodal normals that differ from each other (a curved field).
  const std::vector<V> x{{0, 0}, {2, 0.3}};
  const std::vector<V> normals{{0.25, -0.968245836551854}, {-0.05, -0.998749217771909}};
  const V y0{2.4, -0.1}, y1{0.9, -0.25}, y2{-0.6, -0.05};
  for (bool reference : {false, true}) {
    const std::vector<V> measure = reference ? std::vector<V>{{0.0, 0.05}, {2.1, 0.3}} : std::vector<V>{};
    const std::vector<std::vector<V>> two{{y0, y1}, {y1, y2}};
    const std::vector<std::vector<V>> three{{y0, y1, 0.5 * (y0 + y1)}, {y1, y2, 0.5 * (y1 + y2)}};
    const SegmentMortar<double> a = integrate_segment<double>(x, normals, two, 0.4, 6, measure);
    const SegmentMortar<double> b = integrate_segment<double>(x, normals, three, 0.4, 6, measure);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(a.D[k], b.D[k], 1e-14) << k;
      for (std::size_t f = 0; f < 2; ++f) {
        V va{0, 0}, vb{0, 0};
        for (std::size_t m = 0; m < 2; ++m) va = va + a.M[f][k][m] * two[f][m];
        for (std::size_t m = 0; m < 3; ++m) vb = vb + b.M[f][k][m] * three[f][m];
        EXPECT_NEAR(va.x, vb.x, 1e-14) << k << f;
        EXPECT_NEAR(va.y, vb.y, 1e-14) << k << f;
      }
    }
    for (std::size_t f = 0; f < 2; ++f) {
      EXPECT_NEAR(a.overlap[f][0], b.overlap[f][0], 1e-14);
      EXPECT_NEAR(a.overlap[f][1], b.overlap[f][1], 1e-14);
      EXPECT_LT(a.overlap[f][0], a.overlap[f][1]) << "both masters overlap the slave";
    }
  }
}

}  // namespace

// Dual2 keeps its derivatives in place, up to kDual2MaxVariables variables:
// the product Π (1 + x_i) over that many has the closed-form gradient
// P / (1 + x_i) and Hessian P / ((1 + x_i)(1 + x_k)) (i ≠ k, 0 on the
// diagonal); one more variable is refused.
TEST(Dual2, ProductOfTheLargestNumberOfVariablesAndNoMore) {
  const int n = kDual2MaxVariables;
  std::vector<double> x;
  Dual2 product(1.0);
  for (int i = 0; i < n; ++i) {
    x.push_back(0.05 * i - 0.4);
    product *= Dual2(1.0) + Dual2::variable(x.back(), i, n);
  }
  double p = 1;
  for (double v : x) p *= 1 + v;
  EXPECT_NEAR(product.value(), p, 1e-14 * std::abs(p));
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(product.gradient()[i], p / (1 + x[static_cast<std::size_t>(i)]), 1e-13 * std::abs(p)) << i;
    for (int k = 0; k < n; ++k) {
      const double exact = i == k ? 0.0 : p / ((1 + x[static_cast<std::size_t>(i)]) * (1 + x[static_cast<std::size_t>(k)]));
      EXPECT_NEAR(product.hessian()(i, k), exact, 1e-13 * std::abs(p)) << i << ", " << k;
    }
  }
  EXPECT_THROW(Dual2::variable(0.0, 0, n + 1), std::length_error);
}

// a * b writes the product straight into the result when both carry
// Hessians; it must give the bits of the in-place product Dual2(a) *= b
// (which it replaced), and a first-order evaluation the gradient of the
// second-order one (the term memo serves gradients from Hessian-carrying
// terms), for products, quotients and square roots of mixed values.
TEST(Dual2, DirectProductAndFirstOrderAreBitForBitThoseBefore) {
  const int n = 7;
  std::vector<Dual2> second, first;
  for (int i = 0; i < n; ++i) {
    second.push_back(Dual2::variable(0.3 + 0.17 * i, i, n));
    first.push_back(Dual2::variable(0.3 + 0.17 * i, i, n, false));
  }
  const auto chain_of = [](const std::vector<Dual2>& v) {
    Dual2 r = v[0] * v[1] - v[2] / v[3];
    for (std::size_t k = 2; k + 1 < v.size(); ++k) r = r * (v[k] + sqrt(v[k + 1] * v[k + 1] + r * r)) - Dual2(0.25) * v[k];
    return r;
  };
  const Dual2 a = chain_of(second), b = chain_of(first);
  ASSERT_TRUE(std::isfinite(a.value()));
  Dual2 in_place = a;
  in_place *= second[4] * a;
  const Dual2 direct = a * (second[4] * a);
  EXPECT_EQ(direct.value(), in_place.value());
  EXPECT_TRUE(direct.gradient() == in_place.gradient());
  EXPECT_TRUE(direct.hessian() == in_place.hessian());
  EXPECT_EQ(a.value(), b.value());
  EXPECT_TRUE(a.gradient() == b.gradient());
  EXPECT_FALSE(b.second());
}

// Variables and their linear combinations have zero Hessians, which Dual2
// neither stores nor reads (docs/theory/mortar.md "Cost"). The results must
// be the bits of the dense arithmetic all the same: here every operation
// with such operands (sums, differences, negation, products with constants
// and with each other, fused accumulation, the chain rule, copies) against
// the entries written out by hand in the order Dual2 computes them, and
// the Hessians asked for are zero where they must be.
TEST(Dual2, ZeroHessiansAreSkippedWithTheSameBits) {
  const int n = 4;
  const double xv = 0.7, yv = -1.3, zv = 2.9;
  const Dual2 x = Dual2::variable(xv, 0, n), y = Dual2::variable(yv, 2, n), z = Dual2::variable(zv, 3, n);
  Dual2 copy = x;
  EXPECT_TRUE(copy.hessian() == Dual2::Hessian::Zero(n, n));
  // linear combinations stay linear
  const Dual2 l = Dual2(0.3) * x - y + x.affine(5.0, -0.5) + (-z);
  EXPECT_EQ(l.value(), ((0.3 * xv - yv) + 5.0) + -zv);
  EXPECT_TRUE(l.hessian() == Dual2::Hessian::Zero(n, n));
  EXPECT_EQ(l.gradient()[0], 0.3 * 1.0 + 1.0 * -0.5);
  // a product of two linear values: H = g_a g_bᵀ + g_b g_aᵀ
  const Dual2 p = l * y;
  const Dual2::Hessian& h = p.hessian();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      EXPECT_EQ(h(i, j), l.gradient()[i] * y.gradient()[j] + y.gradient()[i] * l.gradient()[j]) << i << ", " << j;
  // a curved value times a linear one: H_a b + (g_a g_bᵀ + g_b g_aᵀ), the
  // lower triangle computed and mirrored
  Dual2 q = p;
  q *= z;
  Dual2 acc(0.0);
  acc.add_product(p, z);
  const Dual2 direct = p * z;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int r = std::max(i, j), c = std::min(i, j);
      const double t = h(r, c) * zv + (p.gradient()[r] * z.gradient()[c] + z.gradient()[r] * p.gradient()[c]);
      EXPECT_EQ(q.hessian()(i, j), t) << i << ", " << j;
      EXPECT_EQ(acc.hessian()(i, j), t) << i << ", " << j;
      EXPECT_EQ(direct.hessian()(i, j), t) << i << ", " << j;
    }
  // accumulating onto a linear value, and the chain rule of a linear value
  Dual2 onto = x + z;
  onto.add_product(p, z, true);
  Dual2 s = sqrt(x + Dual2(2.0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      EXPECT_EQ(onto.hessian()(i, j), -direct.hessian()(i, j)) << i << ", " << j;
      const double g_i = i == 0 ? 1.0 : 0.0, g_j = j == 0 ? 1.0 : 0.0;
      const double v = xv + 2.0, root = std::sqrt(v);
      EXPECT_EQ(s.hessian()(i, j), (-0.25 / (root * v) * g_i) * g_j) << i << ", " << j;
    }
}

// Dual2::combination (the closed-form sums over a straight master's Gauss
// points, LinearMasterProjection::sums): value as given, gradient Σ a_k ∇p_k,
// Hessian Σ a_k ∇²p_k + Σ_l (∇q_l w_lᵀ + w_l ∇q_lᵀ), w_l = Σ_k b_lk ∇p_k,
// against the same written out with dense matrices; constants contribute
// nothing, and operands over other variables are refused.
TEST(Dual2, CombinationIsTheWeightedSumWithSymmetricOuterProducts) {
  const int n = 4;
  std::vector<Dual2> v;
  for (int i = 0; i < n; ++i) v.push_back(Dual2::variable(0.4 + 0.3 * i, i, n));
  const Dual2 p0 = v[0] * v[1] + sqrt(v[2] + v[3] * v[3]), p1 = v[1] / (v[2] + Dual2(2.0)), p2 = v[3] + v[0];
  const Dual2 constant(7.0);
  const std::array<const Dual2*, 4> p{&p0, &p1, &constant, &p2};
  const std::array<double, 4> a{0.7, -1.3, 5.0, 0.25};
  const std::array<const Dual2*, 2> q{&p1, &p2};
  const std::array<std::array<double, 4>, 2> b{{{0.5, 2.0, 9.0, -0.75}, {-1.5, 0.1, 9.0, 0.3}}};
  const Dual2 c = Dual2::combination(3.25, p, a, q, b);
  EXPECT_EQ(c.value(), 3.25);
  const std::array<const Dual2*, 3> varying{&p0, &p1, &p2};
  const std::array<double, 3> av{a[0], a[1], a[3]};
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n), w0 = g, w1 = g;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t kk = k < 2 ? k : 3;  // index in p (skipping the constant)
    g += av[k] * varying[k]->gradient();
    h += av[k] * varying[k]->hessian();
    w0 += b[0][kk] * varying[k]->gradient();
    w1 += b[1][kk] * varying[k]->gradient();
  }
  h += p1.gradient() * w0.transpose() + w0 * p1.gradient().transpose();
  h += p2.gradient() * w1.transpose() + w1 * p2.gradient().transpose();
  EXPECT_LT((c.gradient() - g).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((c.hessian() - h).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_GT(h.cwiseAbs().maxCoeff(), 0.1);
  // first order: the gradient only
  const Dual2 f0 = Dual2::variable(0.4, 0, n, false) * Dual2::variable(0.7, 1, n, false);
  const std::array<const Dual2*, 1> pf{&f0};
  const std::array<const Dual2*, 1> qf{&f0};
  const Dual2 cf = Dual2::combination(1.0, pf, std::array<double, 1>{2.0}, qf, std::array<std::array<double, 1>, 1>{{{1.0}}});
  EXPECT_FALSE(cf.second());
  EXPECT_EQ(cf.gradient()[0], 2.0 * 0.7);
  // operands over other variables
  const Dual2 other = Dual2::variable(1.0, 0, n + 1);
  const std::array<const Dual2*, 2> mixed{&p0, &other};
  EXPECT_THROW((void)Dual2::combination(0.0, mixed, std::array<double, 2>{1.0, 1.0}, q,
                                        std::array<std::array<double, 2>, 2>{}),
               std::invalid_argument);
}

// Dual2::embedded (the nodal normals computed over the variables of the
// nodes they depend on, MortarTermCache::face_normals): a value computed over
// 3 variables and embedded as variables 0, 2, 4 of 5 (in order) has the
// entries of the same computation over the 5, bit for bit; out of order
// (4, 0, 2), the same to round-off.
TEST(Dual2, EmbeddedIsTheSameComputationOverMoreVariables) {
  const std::array<double, 3> x{0.3, -1.1, 2.4};
  const std::array<int, 3> to{0, 2, 4};
  const auto f = [](const Dual2& a, const Dual2& b, const Dual2& c) {
    const Dual2 s = sqrt(a * a + b * b + Dual2(1.0));
    return (a * c - b) / s;
  };
  const Dual2 few = f(Dual2::variable(x[0], 0, 3), Dual2::variable(x[1], 1, 3), Dual2::variable(x[2], 2, 3));
  const Dual2 all = f(Dual2::variable(x[0], to[0], 5), Dual2::variable(x[1], to[1], 5), Dual2::variable(x[2], to[2], 5));
  const Dual2 e = few.embedded(to, 5);
  EXPECT_EQ(e.value(), all.value());
  EXPECT_TRUE(e.gradient() == all.gradient());
  EXPECT_TRUE(e.hessian() == all.hessian());
  EXPECT_NE(all.hessian()(4, 2), 0.0);  // entries between embedded variables
  const std::array<int, 3> shuffled{4, 0, 2};
  const Dual2 all_shuffled = f(Dual2::variable(x[0], shuffled[0], 5), Dual2::variable(x[1], shuffled[1], 5),
                               Dual2::variable(x[2], shuffled[2], 5));
  const Dual2 e_shuffled = few.embedded(shuffled, 5);
  EXPECT_TRUE(e_shuffled.gradient() == all_shuffled.gradient());
  EXPECT_LT((e_shuffled.hessian() - all_shuffled.hessian()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_GT(e_shuffled.hessian().cwiseAbs().maxCoeff(), 0.1);
  // a linear value stays flat; a first-order one has no Hessian
  const Dual2 linear = Dual2::variable(1.0, 1, 3) + Dual2::variable(2.0, 2, 3);
  EXPECT_TRUE(linear.embedded(to, 5).hessian() == Dual2::Hessian::Zero(5, 5));
  EXPECT_FALSE(Dual2::variable(1.0, 0, 3, false).embedded(to, 5).second());
  EXPECT_THROW((void)few.embedded(std::array<int, 2>{0, 1}, 5), std::invalid_argument);
}

// The projections take the derivatives of their roots from the implicit
// function theorem (Dual2::implicit_root): here the root of
// F(ξ; a, b) = a ξ² + ξ - b, whose closed form ξ = (√(1 + 4ab) - 1) / (2a)
// evaluated in Dual2 gives the exact gradient and Hessian to compare with
// (F_ξξ = 2a ≠ 0, so the curvature term is exercised).
TEST(Dual2, ImplicitRootMatchesTheClosedForm) {
  const int n = 3;  // a, b and an unused third variable
  const Dual2 a = Dual2::variable(0.7, 0, n), b = Dual2::variable(1.9, 1, n);
  const Dual2 closed = (sqrt(Dual2(1.0) + Dual2(4.0) * a * b) - Dual2(1.0)) / (Dual2(2.0) * a);
  const double xi = closed.value();
  const Dual2 x(xi);  // ξ held fixed
  const Dual2 f = a * x * x + x - b, df = Dual2(2.0) * a * x + Dual2(1.0);
  const Dual2 root = Dual2::implicit_root(xi, f, df, 2 * a.value());
  EXPECT_EQ(root.value(), xi);
  EXPECT_LT((root.gradient() - closed.gradient()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((root.hessian() - closed.hessian()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_GT(std::abs(root.hessian()(0, 1)), 0.1);  // a non-trivial Hessian
  const Dual2::Hessian h = root.hessian();
  EXPECT_TRUE(h == h.transpose());
  // F independent of the variables: a constant root.
  EXPECT_TRUE(Dual2::implicit_root(0.5, Dual2(0.0), Dual2(2.0), 1.0).constant());
}
