// *AMPLITUDE, *BOUNDARY, *CLOAD, *DLOAD, *DSLOAD and the OP=MOD/NEW bookkeeping.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// Merges `added` into the list in force: OP=NEW (once per step and `kind`,
/// default the keyword) clears what was inherited, then entries with the same
/// key are replaced (after `check_replace(old, new)`, which may throw), others appended.
template <class T, class KeyFn, class CheckFn>
void merge(DeckState& state, std::vector<T>& list, std::vector<T> added, const KeywordBlock& block,
           const ParameterValues& params, KeyFn key, CheckFn check_replace, const std::string& kind) {
  if (params.name("OP") == "NEW") {
    if (!state.in_step) {
      state.warn(block.where, "OP=NEW has no effect in model data");
    } else if (std::find(state.cleared_this_step.begin(), state.cleared_this_step.end(), kind) ==
               state.cleared_this_step.end()) {
      list.clear();
      state.cleared_this_step.push_back(kind);
    }
  }
  std::unordered_map<long long, std::size_t> index;
  for (std::size_t i = 0; i < list.size(); ++i) index[key(list[i])] = i;
  for (T& a : added) {
    const auto [it, inserted] = index.emplace(key(a), list.size());
    if (inserted) {
      list.push_back(std::move(a));
    } else {
      check_replace(list[it->second], a);
      list[it->second] = std::move(a);
    }
  }
}

template <class T, class KeyFn>
void merge(DeckState& state, std::vector<T>& list, std::vector<T> added, const KeywordBlock& block,
           const ParameterValues& params, KeyFn key) {
  merge(state, list, std::move(added), block, params, key, [](const T&, const T&) {}, block.keyword);
}

long long node_dof_key(int node, int dof) { return 8LL * node + dof; }
long long face_key(const ElementFace& f) { return 8LL * f.element + f.face; }

/// Dofs (0-based) of an ABAQUS boundary type name in 2D; nullopt if unknown.
std::optional<std::vector<int>> boundary_type_dofs(const std::string& type) {
  if (type == "ENCASTRE" || type == "PINNED" || type == "ZASYMM") return std::vector<int>{0, 1};
  if (type == "XSYMM" || type == "YASYMM") return std::vector<int>{0};
  if (type == "YSYMM" || type == "XASYMM") return std::vector<int>{1};
  if (type == "ZSYMM") return std::vector<int>{};
  return std::nullopt;
}

/// Dofs (0-based, 0..1) of a `first[, last]` range; warns once per block about
/// out-of-plane / rotational dofs that are ignored, errors for meaningless ones.
std::vector<int> boundary_range_dofs(DeckState& state, const std::vector<std::string>& f, double value,
                                     const SourceLocation& at, bool& warned) {
  const int first = parse_int(f[1], at, "first dof");
  const int last = (f.size() > 2 && !f[2].empty()) ? parse_int(f[2], at, "last dof") : first;
  if (first < 1 || last < first || last > 6)
    throw InputError(at, "bad dof range " + std::to_string(first) + ".." + std::to_string(last) +
                             ": expected 1 <= first <= last <= 6 (2D models use dofs 1 and 2)");
  if (first == 6 && last == 6) return {2};  // in-plane rotation: exists at *MPC BEAM reference nodes
  if (first >= 4)
    throw InputError(at, "dof " + std::to_string(first) + " is a rotation, which 2D continuum elements do not "
                         "have: expected dof 1 or 2 (or dof 6 alone, the in-plane rotation of an *MPC BEAM "
                         "reference node)");
  if (last >= 3 && value != 0)
    throw InputError(at, "non-zero prescribed value on out-of-plane dof 3: tether is 2D; expected dofs 1-2");
  if (last >= 3 && !warned) {
    state.warn(at, "dofs 3-6 ignored: a 2D model has only dofs 1 and 2");
    warned = true;
  }
  std::vector<int> dofs;
  for (int d = first; d <= std::min(last, 2); ++d) dofs.push_back(d - 1);
  return dofs;
}

long long body_key(const BodyLoad& b) { return 2LL * b.element + static_cast<int>(b.kind); }

/// tether keeps one gravity per element: a second one in another direction
/// is refused (CalculiX would add the two, ABAQUS replace the first).
void check_gravity_replacement(const BodyLoad& old, const BodyLoad& added) {
  if (added.kind != BodyLoad::Kind::Gravity || (old.direction - added.direction).norm() <= 1e-12) return;
  throw InputError(added.where, "GRAV in another direction on an element that already carries GRAV (from " +
                                    old.where.str() + "): tether keeps one gravity load per element (CalculiX adds "
                                    "the two, ABAQUS replaces the first); write the resultant on one line, or "
                                    "remove the first with OP=NEW");
}

/// Three components starting at field `first` (empty or missing: 0).
Eigen::Vector3d vector_fields(const std::vector<std::string>& f, std::size_t first, const SourceLocation& at,
                              const std::string& what) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < 3; ++i)
    if (first + i < f.size() && !f[first + i].empty())
      v[static_cast<Eigen::Index>(i)] = parse_real(f[first + i], at, what + " component " + std::to_string(i + 1));
  return v;
}

/// The elements' families allow this body load: a rotation axis along z for
/// plane elements, the symmetry axis (y through r = 0) for axisymmetric ones.
void check_body_load_geometry(const DeckState& state, const BodyLoad& b, const std::string& token) {
  const Element& e = state.model.elements[static_cast<std::size_t>(b.element)];
  const bool axisymmetric = e.type.family == Family::Axisymmetric;
  constexpr double kTol = 1e-12;
  const std::string elem = "element " + label_text(state.model.instances, e.id) + " (" + std::string(e.type.name) + ") of " + token;
  if (b.kind == BodyLoad::Kind::Gravity) {
    if (std::abs(b.direction.z()) > kTol)
      throw InputError(b.where, "GRAV direction has an out-of-plane (z) component: " + elem +
                                    " is 2D; expected a direction in the x-y plane, e.g. `0, -1, 0`");
    return;
  }
  if (!axisymmetric && (std::abs(b.direction.x()) > kTol || std::abs(b.direction.y()) > kTol))
    throw InputError(b.where, "CENTRIF axis must be the z axis (0, 0, 1) for " + elem +
                                  ": a plane model rotates in its plane");
  if (axisymmetric && (std::abs(b.direction.x()) > kTol || std::abs(b.direction.z()) > kTol ||
                       std::abs(b.point.x()) > kTol * (1 + b.point.norm())))
    throw InputError(b.where, "CENTRIF on " + elem + " must spin about the symmetry axis: expected the point "
                                  "`0, y, 0` and the axis `0, 1, 0`");
}

/// The GRAV or CENTRIF loads of one *DLOAD data line, one per element:
/// `elset, GRAV, g, dx, dy[, dz]` or `elset, CENTRIF, omega^2, px, py, pz, ax, ay, az`.
std::vector<BodyLoad> body_loads_of_line(DeckState& state, const std::vector<std::string>& f,
                                         const SourceLocation& at, int amplitude) {
  BodyLoad b;
  b.where = at;
  b.amplitude = amplitude;
  const std::string type = to_upper(f[1]);
  if (type == "GRAV") {
    if (f.size() < 5 || f.size() > 6)
      throw InputError(at, "expected `element_or_elset, GRAV, g, dx, dy[, dz]` (magnitude and direction)");
    b.magnitude = parse_real(f[2], at, "gravity magnitude");
    b.direction = vector_fields(f, 3, at, "gravity direction");
  } else {
    if (f.size() != 9)
      throw InputError(at, "expected `element_or_elset, CENTRIF, omega^2, px, py, pz, ax, ay, az` (omega^2, a "
                           "point on the axis and the axis direction)");
    b.kind = BodyLoad::Kind::Centrifugal;
    b.magnitude = parse_real(f[2], at, "CENTRIF magnitude omega^2");
    if (b.magnitude < 0)
      throw InputError(at, "CENTRIF magnitude " + f[2] + ": expected omega^2 >= 0 (the square of the angular speed)");
    b.point = vector_fields(f, 3, at, "CENTRIF point");
    b.direction = vector_fields(f, 6, at, "CENTRIF axis");
  }
  if (!(b.direction.norm() > 0))
    throw InputError(at, std::string(type == "GRAV" ? "GRAV direction" : "CENTRIF axis") +
                             " is zero: expected a non-zero vector (it is normalized)");
  b.direction.normalize();
  std::vector<BodyLoad> out;
  for (int e : state.elements_of(f[0], at)) {
    b.element = e;
    check_body_load_geometry(state, b, f[0]);
    out.push_back(b);
  }
  return out;
}

}  // namespace

void handle_amplitude(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Amplitude a;
  a.name = params.name("NAME");
  a.total_time = params.name("TIME") == "TOTAL TIME";
  a.where = block.where;
  for (const Amplitude& other : state.model.amplitudes)
    if (other.name == a.name)
      throw InputError(block.where, "duplicate amplitude " + a.name + ": already defined at " + other.where.str());
  require_data(block, "pairs `t, a`");
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 0, "pairs `t, a`");
    if (f.size() % 2 != 0)
      throw InputError(at, "odd number of values (" + std::to_string(f.size()) + "): expected pairs `t, a`");
    for (std::size_t i = 0; i < f.size(); i += 2) {
      const double t = parse_real(f[i], at, "amplitude time");
      if (!a.times.empty() && !(t > a.times.back()))
        throw InputError(at, "amplitude time " + f[i] + " does not increase: expected times in strictly "
                             "increasing order");
      a.times.push_back(t);
      a.values.push_back(parse_real(f[i + 1], at, "amplitude value"));
    }
  }
  state.model.amplitudes.push_back(std::move(a));
}

void handle_boundary(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  const bool velocity = params.name("TYPE") == "VELOCITY";
  if (velocity && !state.in_step)
    throw InputError(block.where, "*BOUNDARY, TYPE=VELOCITY is history data: expected it inside a step "
                                  "(*STEP ... *END STEP)");
  const bool fixed = params.given("FIXED");
  if (fixed && !state.in_step)
    throw InputError(block.where, "*BOUNDARY, FIXED in model data: FIXED holds dofs at their values at the start "
                                  "of a step, so it belongs inside a *STEP");
  if (fixed && params.given("AMPLITUDE"))
    throw InputError(block.where, "*BOUNDARY, FIXED with AMPLITUDE=: a fixed dof keeps its value, there is nothing "
                                  "to scale; remove one of the two");
  std::vector<Prescribed> added;
  bool warned = false;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 4, "`node_or_nset, first_dof[, last_dof[, value]]` or `node_or_nset, TYPE`");
    if (fixed && f.size() > 3 && !f[3].empty())
      throw InputError(at, "*BOUNDARY, FIXED takes no value (the dof keeps its value at the start of the step): "
                           "expected `node_or_nset, first_dof[, last_dof]`");
    std::vector<int> dofs;
    double value = 0;
    if (!is_integer_token(f[1])) {
      const auto typed = boundary_type_dofs(to_upper(f[1]));
      if (!typed || f.size() > 2)
        throw InputError(at, "bad boundary type '" + f[1] + "': expected a dof number or one of ENCASTRE, "
                                                            "PINNED, XSYMM, YSYMM, XASYMM, YASYMM, ZASYMM, ZSYMM");
      if (velocity)
        throw InputError(at, "boundary type " + to_upper(f[1]) + " with TYPE=VELOCITY: expected "
                             "`node_or_nset, first_dof[, last_dof[, velocity]]`");
      if (typed->empty()) state.warn(at, "ZSYMM ignored: it constrains only out-of-plane dofs");
      dofs = *typed;
    } else {
      if (f.size() > 3 && !f[3].empty()) value = parse_real(f[3], at, velocity ? "prescribed velocity" : "prescribed value");
      dofs = boundary_range_dofs(state, f, value, at, warned);
    }
    for (int n : state.nodes_of(f[0], at))
      for (int d : dofs) added.push_back({n, d, value, amplitude, at, velocity, fixed});
  }
  merge(state, state.boundary, std::move(added), block, params,
        [](const Prescribed& p) { return node_dof_key(p.node, p.dof); });
}

void handle_cload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<ConcentratedLoad> added;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`node_or_nset, dof, magnitude`");
    const int dof = parse_int(f[1], at, "dof");
    const double magnitude = parse_real(f[2], at, "load magnitude");
    if (dof == 3 && magnitude == 0) {
      state.warn(at, "zero load on out-of-plane dof 3 ignored (2D model)");
      continue;
    }
    if (dof != 1 && dof != 2 && dof != 6)
      throw InputError(at, "bad load dof " + f[1] + ": expected dof 1 or 2 (2D model), or 6 (a moment on an "
                           "*MPC BEAM reference node)");
    const int index = dof == 6 ? 2 : dof - 1;
    for (int n : state.nodes_of(f[0], at)) added.push_back({n, index, magnitude, amplitude, at});
  }
  merge(state, state.cloads, std::move(added), block, params,
        [](const ConcentratedLoad& c) { return node_dof_key(c.node, c.dof); });
}

void handle_dload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<PressureLoad> added;
  std::vector<BodyLoad> body;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 0, "`element_or_elset, P1..P4, magnitude` or a GRAV or CENTRIF load");
    const std::string type = to_upper(f[1]);
    if (type == "GRAV" || type == "CENTRIF") {
      for (BodyLoad& b : body_loads_of_line(state, f, at, amplitude)) body.push_back(std::move(b));
      continue;
    }
    if (f.size() > 3)
      throw InputError(at, "expected `element_or_elset, P1..P4, magnitude` (or GRAV, CENTRIF) but found '" +
                               line.text + "'");
    const double magnitude = parse_real(f[2], at, "pressure magnitude");
    for (int e : state.elements_of(f[0], at)) {
      const int face = parse_face_id(f[1], state.model, state.model.elements[static_cast<std::size_t>(e)], at, 'P');
      added.push_back({{e, face}, magnitude, amplitude, at});
    }
  }
  merge(state, state.dloads, std::move(added), block, params, [](const PressureLoad& p) { return face_key(p.face); });
  merge(state, state.body_loads, std::move(body), block, params, body_key, check_gravity_replacement,
        "DLOAD BODY");
}

void handle_dsload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<PressureLoad> added;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`surface, P, magnitude`");
    const auto it = state.model.surfaces.find(to_upper(f[0]));
    if (it == state.model.surfaces.end())
      throw InputError(at, "undefined surface '" + f[0] + "': expected a surface defined by *SURFACE");
    if (it->second.kind != Surface::Kind::ElementFaces)
      throw InputError(at, "surface " + it->second.name + " is a node surface: expected an element-face surface "
                           "(TYPE=ELEMENT) for a pressure");
    if (to_upper(f[1]) != "P") throw InputError(at, "bad load type '" + f[1] + "': expected P (pressure)");
    const double magnitude = parse_real(f[2], at, "pressure magnitude");
    for (const ElementFace& face : it->second.faces) added.push_back({face, magnitude, amplitude, at});
  }
  merge(state, state.dsloads, std::move(added), block, params, [](const PressureLoad& p) { return face_key(p.face); });
}

}  // namespace tether::deck
