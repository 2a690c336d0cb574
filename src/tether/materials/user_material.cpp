#include "tether/materials/user_material.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fmt/format.h>

#include "tether/core/shared_library.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

/// tether's Voigt index of ABAQUS component k (NTENS = 4: 11, 22, 33, 12; NTENS = 3: 11, 22, 12).
int voigt_index(int ntens, int k) {
  static constexpr int kFour[4] = {0, 1, 2, 3}, kThree[3] = {0, 1, 3};
  return ntens == 4 ? kFour[k] : kThree[k];
}

/// 3x3 column-major I + eps (tensor) of a Voigt strain (engineering shear).
std::array<double, 9> small_strain_gradient(const Vec6& e) {
  return {1 + e(0), 0.5 * e(3), 0.5 * e(5), 0.5 * e(3), 1 + e(1), 0.5 * e(4), 0.5 * e(5), 0.5 * e(4), 1 + e(2)};
}

bool all_finite(const double* v, std::size_t n) {
  return std::all_of(v, v + n, [](double x) { return std::isfinite(x); });
}

}  // namespace

UserMaterial::UserMaterial(std::string name, const std::string& library, std::string symbol,
                           std::vector<double> props, int n_statev)
    : name_(std::move(name)),
      symbol_(symbol.empty() ? std::string(TETHER_UMAT_DEFAULT_SYMBOL) : std::move(symbol)),
      props_(std::move(props)),
      n_statev_(n_statev) {
  library_ = SharedLibrary::open(library);
  std::string error;
  void* address = library_->symbol(symbol_, error);
  if (address == nullptr)
    throw ModelError("shared library '" + library + "' has no routine '" + symbol_ + "' (" + error +
                     "); a Fortran SUBROUTINE UMAT compiled by gfortran is 'umat_'");
  routine_ = reinterpret_cast<tether_umat_fn>(address);
  cmname_.fill(' ');
  for (std::size_t i = 0; i < name_.size() && i < cmname_.size(); ++i)
    cmname_[i] = static_cast<char>(std::toupper(static_cast<unsigned char>(name_[i])));
  // Zero-strain call: the initial shear stiffness, and a first check of the routine.
  std::vector<double> state(static_cast<std::size_t>(n_state()), 0.0), next(state.size());
  Vec6 eps = Vec6::Zero();
  MaterialResponse r;
  update_small_strain(eps, false, state, next, PointContext{}, r);
  mu_ = r.tangent(3, 3);
}

std::string UserMaterial::describe() const {
  return fmt::format("user material {} ({} in {}, {} constants, {} state variables)", name_, symbol_,
                     library_->path(), props_.size(), n_statev_);
}

void UserMaterial::update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                                       std::span<double> new_state, const PointContext& where,
                                       MaterialResponse& out) const {
  const int ntens = plane_stress ? 3 : 4;
  if (plane_stress) eps(2) = 0;  // not known for a user material
  const Eigen::Map<const Vec6> stress_old(old_state.data()), strain_old(old_state.data() + 6);
  UmatCall c;
  c.ntens = ntens;
  for (int k = 0; k < ntens; ++k) {
    const int v = voigt_index(ntens, k);
    c.stress[k] = stress_old(v);
    c.stran[k] = strain_old(v);
    c.dstran[k] = eps(v) - strain_old(v);
  }
  c.dfgrd0 = small_strain_gradient(strain_old), c.dfgrd1 = small_strain_gradient(eps);
  call_routine(c, old_state, new_state, where);
  out.stress.setZero();
  out.tangent.setZero();
  for (int i = 0; i < ntens; ++i) {
    out.stress(voigt_index(ntens, i)) = c.stress[i];
    for (int j = 0; j < ntens; ++j) out.tangent(voigt_index(ntens, i), voigt_index(ntens, j)) = c.ddsdde[i + ntens * j];
  }
  out.elastic_energy = c.sse;
  out.dissipation = c.spd - old_state[13];
  Eigen::Map<Vec6>(new_state.data()) = out.stress;
  Eigen::Map<Vec6>(new_state.data() + 6) = eps;
  // U - I = eps (tensor shear): where a later NLGEOM step starts from.
  Eigen::Map<Vec6>(new_state.data() + 15) << eps(0), eps(1), eps(2), 0.5 * eps(3), 0.5 * eps(4), 0.5 * eps(5);
}

void UserMaterial::call_routine(UmatCall& c, std::span<const double> old_state, std::span<double> new_state,
                                const PointContext& where) const {
  const int ntens = c.ntens, ndi = ntens == 3 ? 2 : 3, nshr = 1, nprops = static_cast<int>(props_.size());
  c.sse = old_state[12], c.spd = old_state[13], c.scd = old_state[14];
  std::copy(old_state.begin() + kHeader, old_state.end(), new_state.begin() + kHeader);
  double* statev = new_state.data() + kHeader;
  double rpl = 0, ddsddt[4] = {}, drplde[4] = {}, drpldt = 0, predef = 0, dpred = 0;
  const double temp = where.temperature - where.temperature_increment, dtemp = where.temperature_increment;
  const double time[2] = {where.step_time - where.dt, where.total_time - where.dt}, dtime = where.dt;
  const double coords[3] = {where.x, where.y, 0}, celent = 0;
  double pnewdt = 1e36;
  const int nstatv = n_statev_, layer = 1, kspt = 1, kstep = 0, kinc = 0;
  std::fill(std::begin(c.ddsdde), std::end(c.ddsdde), 0.0);
  routine_(c.stress, statev, c.ddsdde, &c.sse, &c.spd, &c.scd, &rpl, ddsddt, drplde, &drpldt, c.stran, c.dstran,
           time, &dtime, &temp, &dtemp, &predef, &dpred, cmname_.data(), &ndi, &nshr, &ntens, &nstatv,
           props_.data(), &nprops, coords, c.drot.data(), &pnewdt, &celent, c.dfgrd0.data(), c.dfgrd1.data(),
           &where.element, &where.point, &layer, &kspt, &kstep, &kinc, cmname_.size());
  const auto at = [&] {
    return where.point > 0 ? fmt::format("user material {} (routine {}), integration point {}", name_, symbol_, where.point)
                           : fmt::format("user material {} (routine {}), in the call at zero strain when the model "
                                         "is built", name_, symbol_);
  };
  if (!all_finite(c.stress, static_cast<std::size_t>(ntens)) ||
      !all_finite(c.ddsdde, static_cast<std::size_t>(ntens * ntens)) ||
      !all_finite(statev, static_cast<std::size_t>(nstatv)) || !std::isfinite(c.sse) || !std::isfinite(c.spd))
    throw ModelError(at() + ": the routine returned a NaN or infinite value");
  if (pnewdt < 1)
    throw ModelError(fmt::format("{}: the routine asks for a smaller increment (PNEWDT = {:g})", at(), pnewdt));
  new_state[12] = c.sse, new_state[13] = c.spd, new_state[14] = c.scd;
}

}  // namespace tether
