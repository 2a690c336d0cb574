#include "tether/elements/continuum_element.hpp"

#include <Eigen/LU>
#include <array>
#include <cassert>
#include <cmath>
#include <memory>
#include <fmt/format.h>
#include <numbers>

#include "tether/assembly/saved_state.hpp"
#include "tether/fem/extrapolation.hpp"
#include "tether/materials/thermal_model.hpp"

namespace tether {

namespace {

/// Shape functions at the points of one rule, the same for every element of
/// a shape (computed once).
const TabulatedShapes& rule_shapes(Shape shape, QuadratureRule rule) {
  static const auto table = [] {
    std::array<std::array<TabulatedShapes, 4>, 4> t;
    for (Shape sh : {Shape::Tri3, Shape::Quad4, Shape::Tri6, Shape::Quad8})
      for (QuadratureRule ru : {QuadratureRule::Triangle1, QuadratureRule::Triangle3, QuadratureRule::Quad2x2,
                                QuadratureRule::Quad3x3}) {
        const bool tri_shape = sh == Shape::Tri3 || sh == Shape::Tri6;
        if (tri_shape != (rule_shape(ru) == Shape::Tri3)) continue;
        t[static_cast<std::size_t>(sh)][static_cast<std::size_t>(ru)] = tabulate_shapes(sh, quadrature_points(ru));
      }
    return t;
  }();
  return table[static_cast<std::size_t>(shape)][static_cast<std::size_t>(rule)];
}

}  // namespace

ContinuumElement::ContinuumElement(int label, const ElementType& type, std::span<const int> node_indices,
                                   const std::vector<Eigen::Vector2d>& node_coords,
                                   const ConstitutiveModel& material, double thickness,
                                   const DofMap& dofs, const MaterialData* material_data)
    : label_(label),
      rule_(default_rule(type)),
      n_nodes_(static_cast<std::uint8_t>(n_nodes(type.shape))),
      n_points_(static_cast<std::uint8_t>(quadrature_points(rule_).size())),
      type_(&intern_element_type(type)),
      node_coords_(node_coords.data()),
      material_(&material),
      material_data_(material_data),
      thickness_(thickness) {
  if (const std::string why = unsupported_reason(type); !why.empty())
    throw ModelError(describe() + ": " + why);
  if (static_cast<int>(node_indices.size()) != n_nodes_)
    throw ModelError(fmt::format("{}: expected {} nodes, got {}", describe(), n_nodes_, node_indices.size()));
  for (const int node : node_indices)
    if (node < 0 || static_cast<std::size_t>(node) >= node_coords.size())
      throw ModelError(fmt::format("{}: node index {} outside the table of {} node coordinates", describe(), node,
                                   node_coords.size()));
  const bool axisymmetric = type.family == Family::Axisymmetric;
  if (!axisymmetric && !(thickness > 0))
    throw ModelError(fmt::format("{}: thickness must be positive (got {:g})", describe(), thickness));

  // The block of storage_: the dofs (x, y per node), then the nodes.
  const auto n = static_cast<std::size_t>(n_nodes_);
  storage_ = std::make_unique_for_overwrite<int[]>(3 * n);
  for (std::size_t a = 0; a < n; ++a) {
    storage_[2 * a] = dofs.displacement(node_indices[a], 0);
    storage_[2 * a + 1] = dofs.displacement(node_indices[a], 1);
    storage_[2 * n + a] = node_indices[a];
  }

  if (const int n_state = material.n_state(); n_state > 0) {
    history_ = std::make_unique<History>();
    history_->n_state = n_state;
    const int record = kRecordState + n_state;
    history_->records.assign(static_cast<std::size_t>(n_points_ * record), 0.0);
    for (int q = 0; q < n_points_; ++q)
      material.initial_state(std::span<double>(history_->records)
                                 .subspan(static_cast<std::size_t>(q * record + kRecordState),
                                          static_cast<std::size_t>(n_state)));
    history_->committed_u.assign(static_cast<std::size_t>(2 * n_nodes_), 0.0);
  }

  PointGeometry g;
  const NodeCoordinates X = reference_coords();
  for (int q = 0; q < n_points_; ++q) {
    const double detJ = point_geometry(q, X, g);
    if (!(detJ > 0))
      throw ModelError(fmt::format(
          "{}: Jacobian determinant {:.3g} <= 0 at integration point {} in the reference "
          "configuration (distorted element or clockwise node order)",
          describe(), detJ, q + 1));
    if (axisymmetric && !(g.R > 0))
      throw ModelError(fmt::format("{}: integration point {} lies at r = {:.3g} <= 0", describe(),
                                   q + 1, g.R));
  }
}

template <int NN>
ContinuumElement::NodeCoordinates ContinuumElement::reference_coords() const {
  NodeCoordinates X;
  const int n = NN == Eigen::Dynamic ? n_nodes_ : NN;
  const int* node = nodes().data();
  for (int a = 0; a < n; ++a) X[static_cast<std::size_t>(a)] = node_coords_[node[a]];
  return X;
}

template <int NN>
double ContinuumElement::point_geometry(int q, const NodeCoordinates& X, PointGeometry& g) const {
  const TabulatedShapes& shapes = rule_shapes(type_->shape, rule_);
  const ShapeVector& N = shapes.N[static_cast<std::size_t>(q)];
  const ShapeGradient& dN = shapes.dN[static_cast<std::size_t>(q)];
  const int n = NN == Eigen::Dynamic ? n_nodes_ : NN;
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i,j) = dX_i/dxi_j
  Eigen::Vector2d Xq = Eigen::Vector2d::Zero();
  for (int a = 0; a < n; ++a) {
    J += X[static_cast<std::size_t>(a)] * dN.row(a);
    Xq += N(a) * X[static_cast<std::size_t>(a)];
  }
  const double detJ = J.determinant();
  g.N = N;
  g.R = Xq.x();
  g.Y = Xq.y();
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  const double measure = axisymmetric ? 2 * std::numbers::pi * Xq.x() : thickness_;
  g.dV = shapes.weight[static_cast<std::size_t>(q)] * detJ * measure;
  if (!(detJ > 0)) {
    g.G.setZero(n, 2);
  } else if constexpr (NN == Eigen::Dynamic) {
    g.G = dN * J.inverse();  // dN/dX
  } else {  // the same products, of fixed size (the columns of a ShapeGradient are rows() apart)
    g.G.resize(NN, 2);
    Eigen::Map<Eigen::Matrix<double, NN, 2>>(g.G.data()).noalias() =
        Eigen::Map<const Eigen::Matrix<double, NN, 2>>(dN.data()) * J.inverse();
  }
  return detJ;
}

// The hybrid path (continuum_element_hybrid.cpp) and the once-per-increment
// paths use the run-time node count.
template ContinuumElement::NodeCoordinates ContinuumElement::reference_coords<Eigen::Dynamic>() const;
template double ContinuumElement::point_geometry<Eigen::Dynamic>(int, const NodeCoordinates&, PointGeometry&) const;

std::string ContinuumElement::describe() const {
  return name_ == nullptr ? fmt::format("element {} ({})", label_, type_->name)
                          : fmt::format("element {} ({})", *name_, type_->name);
}

void ContinuumElement::set_name(std::string name) {
  if (name.empty() || name == std::to_string(label_)) name_.reset();  // describe() gives the same text
  else name_ = std::make_unique<const std::string>(std::move(name));
}

void ContinuumElement::gather(const Eigen::VectorXd& u, Eigen::Ref<Eigen::VectorXd> ue) const {
  const int* d = dofs().data();
  for (int i = 0; i < 2 * n_nodes_; ++i) ue(i) = u(d[i]);
}

std::span<const double> ContinuumElement::committed_state(int q) const {
  if (n_state() == 0) return {};
  const int record = kRecordState + n_state();
  return std::span<const double>(history_->records).subspan(static_cast<std::size_t>(q * record + kRecordState),
                                                   static_cast<std::size_t>(n_state()));
}

bool ContinuumElement::committed_at(const Eigen::Ref<const Eigen::VectorXd>& ue, double total_time) const {
  if (n_state() == 0) return false;
  if (total_time != history_->committed_time) return false;  // a rate-dependent material differs at the same strain
  for (int i = 0; i < 2 * n_nodes_; ++i)
    if (ue(i) != history_->committed_u[static_cast<std::size_t>(i)]) return false;
  return true;
}

PointContext ContinuumElement::context(const EvaluationState& s, int q, const PointGeometry& g) const {
  PointContext c;
  c.element = label_;
  c.point = q + 1;
  c.x = g.R;
  c.y = g.Y;
  c.step_time = s.step_time;
  c.total_time = s.total_time;
  c.dt = s.dt;
  if (temperatures_ != nullptr)
    for (int a = 0; a < n_nodes_; ++a) {
      const int node = nodes()[static_cast<std::size_t>(a)];
      const double end = temperatures_->current(node, s.step_time, s.total_time);
      c.temperature += g.N(a) * end;
      c.temperature_increment += g.N(a) * (end - temperatures_->current(node, s.step_time - s.dt, s.total_time - s.dt));
      c.initial_temperature += g.N(a) * temperatures_->initial(node);
    }
  return c;
}

void ContinuumElement::material_point(int q, const PointGeometry& g, const double* ue, const EvaluationState& s,
                                      MaterialPoint& mp, std::span<double> trial, double mean) const {
  const int n = n_nodes_;
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
  double ur = 0;
  for (int a = 0; a < n; ++a) {
    H(0, 0) += ue[2 * a] * g.G(a, 0);
    H(0, 1) += ue[2 * a] * g.G(a, 1);
    H(1, 0) += ue[2 * a + 1] * g.G(a, 0);
    H(1, 1) += ue[2 * a + 1] * g.G(a, 1);
    ur += ue[2 * a] * g.N(a);
  }
  const double hoop = ur / g.R;
  if (type_->hybrid) return hybrid_point(q, g, H, hoop, mean, s, mp, trial);
  if (s.nlgeom)
    finite_strain_point(*material_, type_->family, H, hoop, committed_state(q), trial, context(s, q, g), mp);
  else
    small_strain_point(*material_, type_->family, H, hoop, committed_state(q), trial, context(s, q, g), mp);
}

template <int NN>
void ContinuumElement::evaluate_kernel(const double* ue_ptr, const EvaluationState& s, LocalSystem& out,
                                       bool need_tangent) const {
  const bool nlgeom = s.nlgeom;
  constexpr int ND = 2 * NN;
  assert(out.residual.size() == ND && (!need_tangent || out.tangent.rows() == ND));
  using Nodal = Eigen::Matrix<double, NN, 1>;
  const Eigen::Map<const Eigen::Matrix<double, 2, NN>> U(ue_ptr);  // column a = displacement of node a
  Eigen::Map<Eigen::Matrix<double, ND, 1>> r(out.residual.data());
  Eigen::Map<Eigen::Matrix<double, ND, ND>> K(out.tangent.data());
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  MaterialPoint mp;
  Eigen::Matrix<double, 4, ND> B;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));  // discarded: evaluate() commits nothing
  const NodeCoordinates X = reference_coords<NN>();
  for (int q = 0; q < n_points_; ++q) {
    point_geometry<NN>(q, X, g);
    const Eigen::Map<const Nodal> N(g.N.data()), Gx(g.G.data()), Gy(g.G.data() + NN);
    const double dV = g.dV, R = g.R;
    Eigen::Matrix2d H;
    H.col(0).noalias() = U * Gx;
    H.col(1).noalias() = U * Gy;
    const double hoop = axisymmetric ? U.row(0).dot(N) / R : 0.0;
    if (nlgeom)
      finite_strain_point(*material_, type_->family, H, hoop, committed_state(q), trial, context(s, q, g), mp);
    else
      small_strain_point(*material_, type_->family, H, hoop, committed_state(q), trial, context(s, q, g), mp);

    // B: rows (11, 22, 33, 2*12) of the strain variation; F = I for small strain.
    const Eigen::Matrix2d& F = mp.F;
    const double f33_over_r = axisymmetric ? mp.F33 / R : 0.0;
    for (int a = 0; a < NN; ++a) {
      for (int i = 0; i < 2; ++i) {
        B(0, 2 * a + i) = F(i, 0) * Gx(a);
        B(1, 2 * a + i) = F(i, 1) * Gy(a);
        B(3, 2 * a + i) = F(i, 0) * Gy(a) + F(i, 1) * Gx(a);
      }
      B(2, 2 * a) = f33_over_r * N(a);
      B(2, 2 * a + 1) = 0;
    }
    const Eigen::Vector4d stress = mp.stress.head<4>() * dV;
    r.noalias() += B.transpose() * stress;
    if (!need_tangent) continue;

    const Eigen::Matrix<double, 4, ND> DB = (mp.D.topLeftCorner<4, 4>() * dV) * B;
    K.noalias() += B.transpose().lazyProduct(DB);  // small fixed sizes: skip Eigen's GEMM path
    if (nlgeom) {  // geometric stiffness: delta(dE) : S
      for (int a = 0; a < NN; ++a) {
        const double sa0 = stress(0) * Gx(a) + stress(3) * Gy(a);
        const double sa1 = stress(3) * Gx(a) + stress(1) * Gy(a);
        const double hoop_a = axisymmetric ? stress(2) * N(a) / (R * R) : 0.0;
        for (int b = 0; b < NN; ++b) {
          const double g = sa0 * Gx(b) + sa1 * Gy(b);
          K(2 * a, 2 * b) += g + hoop_a * N(b);
          K(2 * a + 1, 2 * b + 1) += g;
        }
      }
    }
  }
}

void ContinuumElement::evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const {
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2 * kMaxElementNodes, 1> ue(2 * n_nodes_);
  gather(s.u, ue);
  try {
    if (type_->hybrid && s.nlgeom) return evaluate_hybrid_finite(ue.data(), s, out, need_tangent);
    if (type_->hybrid) return evaluate_hybrid_small(ue.data(), s, out, need_tangent);
    switch (type_->shape) {
      case Shape::Tri3: evaluate_kernel<3>(ue.data(), s, out, need_tangent); break;
      case Shape::Quad4: evaluate_kernel<4>(ue.data(), s, out, need_tangent); break;
      case Shape::Tri6: evaluate_kernel<6>(ue.data(), s, out, need_tangent); break;
      case Shape::Quad8: evaluate_kernel<8>(ue.data(), s, out, need_tangent); break;
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
}

double ContinuumElement::thickness_stretch(const EvaluationState& s, const Eigen::Vector2d& xi,
                                           Eigen::VectorXd& dF33_du) const {
  if (type_->family != Family::PlaneStress || !s.nlgeom)
    throw ModelError(describe() + ": the thickness stretch is asked of a plane-stress element under NLGEOM only");
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  ShapeVector N;
  ShapeGradient dN;
  shape_functions(type_->shape, xi, N, dN);
  // Weights of the point values at xi: N(xi)^T E, E the extrapolation matrix.
  const Eigen::RowVectorXd w = N.head(n_nodes_).transpose() * extrapolation_matrix(type_->shape, rule_);
  MaterialPoint mp;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));
  double F33 = 0;
  dF33_du.setZero(2 * n_nodes_);
  try {
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      material_point(q, g, ue.data(), s, mp, trial);
      F33 += w(q) * mp.F33;
      const Eigen::Matrix2d d = thickness_stretch_gradient(mp);  // dF33_q / dH, H_ij = sum_a u_ai G_aj
      for (int a = 0; a < n_nodes_; ++a) dF33_du.segment<2>(2 * a) += w(q) * (d * g.G.row(a).transpose());
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  return F33;
}

double ContinuumElement::strain_energy(const EvaluationState& s) const {
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  const bool from_records = committed_at(ue, s.total_time);
  const int record = kRecordState + n_state();
  MaterialPoint mp;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));
  double energy = 0;
  try {
    const double mean = element_mean(ue.data(), s.nlgeom);
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      if (from_records) {
        energy += history_->records[static_cast<std::size_t>(q * record + kRecordEnergy)] * g.dV;
        continue;
      }
      material_point(q, g, ue.data(), s, mp, trial, mean);
      energy += strain_energy_density(*material_, s.nlgeom, mp) * g.dV;
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  return energy;
}

double ContinuumElement::plastic_dissipation(const EvaluationState& s) const {
  if (n_state() == 0) return 0;
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  const bool from_records = committed_at(ue, s.total_time);
  const int record = kRecordState + n_state();
  MaterialPoint mp;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));
  double total = 0;
  try {
    const double mean = element_mean(ue.data(), s.nlgeom);
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      double density = history_->records[static_cast<std::size_t>(q * record + kRecordDissipation)];
      if (!from_records) {
        material_point(q, g, ue.data(), s, mp, trial, mean);
        density += mp.dissipation;
      }
      total += density * g.dV;
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  return total;
}

double ContinuumElement::plastic_dissipation_increment(const EvaluationState& s) const {
  if (n_state() == 0) return 0;
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  if (committed_at(ue, s.total_time)) return 0;
  MaterialPoint mp;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));
  double total = 0;
  try {
    const double mean = element_mean(ue.data(), s.nlgeom);
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      material_point(q, g, ue.data(), s, mp, trial, mean);
      total += mp.dissipation * g.dV;
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  return total;
}

void ContinuumElement::point_values(const EvaluationState& s, std::vector<PointValues>& out) const {
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  out.resize(n_points_);
  const bool from_records = committed_at(ue, s.total_time);
  const int record = kRecordState + n_state();
  MaterialPoint mp;
  PointGeometry g;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));
  const auto* thermal = dynamic_cast<const ThermalModel*>(material_);  // THE (none: zero)
  try {
    const double mean = element_mean(ue.data(), s.nlgeom);
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      material_point(q, g, ue.data(), s, mp, trial, mean);
      std::span<const double> state = trial;
      if (from_records) {  // the committed values of this very state (equal to mp's up to round-off)
        const double* r = history_->records.data() + static_cast<std::ptrdiff_t>(q * record);
        mp.stress = Eigen::Map<const Vec6>(r + kRecordStress);
        mp.strain = Eigen::Map<const Vec6>(r + kRecordStrain);
        state = committed_state(q);
      }
      Eigen::Vector2d x = Eigen::Vector2d::Zero();
      for (int a = 0; a < n_nodes_; ++a)
        x += g.N(a) * (X[static_cast<std::size_t>(a)] + Eigen::Vector2d(ue(2 * a), ue(2 * a + 1)));
      const Eigen::Vector4d sigma = cauchy_stress(s.nlgeom, mp);
      PointValues& pv = out[q];
      pv.x = x;
      pv.stress = {sigma(0), sigma(1), sigma(2), sigma(3)};
      pv.strain = {mp.strain(0), mp.strain(1), mp.strain(2), 0.5 * mp.strain(3)};
      pv.peeq = material_->equivalent_plastic_strain(state);
      pv.ac_yield = material_->actively_yielding(state) ? 1 : 0;
      const Vec6 pe = material_->plastic_strain(state);
      pv.plastic_strain = {pe(0), pe(1), pe(2), 0.5 * pe(3)};
      const double eth = thermal ? thermal->thermal_strain(context(s, q, g)) : 0.0;
      pv.thermal_strain = {eth, eth, eth, 0.0};
      const std::span<const double> user = material_->user_state(state);
      pv.sdv.assign(user.begin(), user.end());
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
}

void ContinuumElement::commit(const EvaluationState& s) {
  if (n_state() == 0) return;
  Eigen::VectorXd ue(2 * n_nodes_);
  gather(s.u, ue);
  if (committed_at(ue, s.total_time)) return;  // already the committed state of these displacements
  const int record = kRecordState + n_state();
  std::vector<double> next(history_->records.size());
  MaterialPoint mp;
  PointGeometry g;
  try {
    const double mean = element_mean(ue.data(), s.nlgeom);
    const NodeCoordinates X = reference_coords();
    for (int q = 0; q < n_points_; ++q) {
      point_geometry(q, X, g);
      double* r = next.data() + static_cast<std::ptrdiff_t>(q * record);
      material_point(q, g, ue.data(), s, mp, std::span<double>(r + kRecordState, n_state()), mean);
      Eigen::Map<Vec6>(r + kRecordStress) = mp.stress;
      Eigen::Map<Vec6>(r + kRecordStrain) = mp.strain;
      r[kRecordEnergy] = mp.elastic_energy;
      r[kRecordDissipation] = history_->records[static_cast<std::size_t>(q * record + kRecordDissipation)] + mp.dissipation;
    }
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  history_->records.swap(next);
  history_->committed_u.assign(ue.data(), ue.data() + ue.size());
  history_->committed_time = s.total_time;
}

namespace {
constexpr double kHistoryTag = 7302;  ///< first value of a ContinuumElement's saved state (7301: stamp without the time)
}  // namespace

void ContinuumElement::save_state(std::vector<double>& out) const {
  if (n_state() == 0) return;
  out.push_back(kHistoryTag);
  out.push_back(n_points_);
  out.push_back(kRecordState + n_state());
  out.insert(out.end(), history_->records.begin(), history_->records.end());
  out.insert(out.end(), history_->committed_u.begin(), history_->committed_u.end());
  out.push_back(history_->committed_time);
}

void ContinuumElement::load_state(std::span<const double>& in) {
  if (n_state() == 0) return;
  saved_state::expect_tag(in, kHistoryTag, "continuum element with material history");
  saved_state::take_int(in, n_points_, n_points_, "number of integration points");
  const int record = kRecordState + n_state();
  saved_state::take_int(in, record, record, "history record size");
  const std::size_t n = history_->records.size() + history_->committed_u.size() + 1;
  if (in.size() < n) throw std::runtime_error("its saved state is too short");
  std::copy(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(history_->records.size()), history_->records.begin());
  in = in.subspan(history_->records.size());
  std::copy(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(history_->committed_u.size()), history_->committed_u.begin());
  in = in.subspan(history_->committed_u.size());
  history_->committed_time = in.front();
  in = in.subspan(1);
}

void ContinuumElement::mass(MassKind kind, Eigen::MatrixXd& out) const {
  if (material_data_ == nullptr)
    throw ModelError(describe() + ": *DENSITY missing: no material data was given to the element");
  if (!material_data_->density)
    throw ModelError(fmt::format("{}: *DENSITY missing for material {} ({})", describe(), material_data_->name,
                                 material_data_->where.str()));
  try {
    const NodeCoordinates X = reference_coords();
    expand_to_components(scalar_mass(kind, *type_, std::span(X.data(), n_nodes_), *material_data_->density, thickness_),
                         2, out);
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
}

void ContinuumElement::extrapolate_to_nodes(const std::vector<PointValues>& points,
                                            std::vector<Tensor4>& nodal_stress,
                                            std::vector<Tensor4>& nodal_strain) const {
  const Eigen::MatrixXd& E = extrapolation_matrix(type_->shape, rule_);
  nodal_stress.assign(n_nodes_, Tensor4{});
  nodal_strain.assign(n_nodes_, Tensor4{});
  for (int a = 0; a < n_nodes_; ++a)
    for (int q = 0; q < n_points_; ++q)
      for (int c = 0; c < 4; ++c) {
        nodal_stress[a][c] += E(a, q) * points[q].stress[c];
        nodal_strain[a][c] += E(a, q) * points[q].strain[c];
      }
}

void ContinuumElement::extrapolate_thermal_to_nodes(const std::vector<PointValues>& points,
                                                    std::vector<Tensor4>& nodal_thermal_strain) const {
  const Eigen::MatrixXd& E = extrapolation_matrix(type_->shape, rule_);
  nodal_thermal_strain.assign(n_nodes_, Tensor4{});
  for (int a = 0; a < n_nodes_; ++a)
    for (int q = 0; q < n_points_; ++q)
      for (int c = 0; c < 4; ++c) nodal_thermal_strain[a][c] += E(a, q) * points[q].thermal_strain[c];
}

void ContinuumElement::extrapolate_plastic_to_nodes(const std::vector<PointValues>& points,
                                                    std::vector<double>& nodal_peeq,
                                                    std::vector<Tensor4>& nodal_plastic_strain) const {
  const Eigen::MatrixXd& E = extrapolation_matrix(type_->shape, rule_);
  nodal_peeq.assign(n_nodes_, 0.0);
  nodal_plastic_strain.assign(n_nodes_, Tensor4{});
  for (int a = 0; a < n_nodes_; ++a)
    for (int q = 0; q < n_points_; ++q) {
      nodal_peeq[a] += E(a, q) * points[q].peeq;
      for (int c = 0; c < 4; ++c) nodal_plastic_strain[a][c] += E(a, q) * points[q].plastic_strain[c];
    }
}

void ContinuumElement::extrapolate_sdv_to_nodes(const std::vector<PointValues>& points, int n,
                                                std::vector<double>& nodal) const {
  const Eigen::MatrixXd& E = extrapolation_matrix(type_->shape, rule_);
  nodal.assign(static_cast<std::size_t>(n_nodes_ * n), 0.0);
  for (int a = 0; a < n_nodes_; ++a)
    for (int q = 0; q < n_points_; ++q) {
      const std::vector<double>& sdv = points[static_cast<std::size_t>(q)].sdv;
      const int own = std::min(n, static_cast<int>(sdv.size()));
      for (int k = 0; k < own; ++k) nodal[static_cast<std::size_t>(a * n + k)] += E(a, q) * sdv[static_cast<std::size_t>(k)];
    }
}

}  // namespace tether
