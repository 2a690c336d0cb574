// *SURFACE INTERACTION, *SURFACE BEHAVIOR, *FRICTION, *CONTACT PAIR and the
// contact output requests (*CONTACT PRINT, *CONTACT FILE, *CONTACT OUTPUT).
#include <algorithm>
#include <cmath>

#include "tether/contact/contact_search.hpp"
#include "tether/contact/master_segments.hpp"
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/model_checks.hpp"
#include "tether/io/numbers.hpp"
#include "tether/model/element_type.hpp"

namespace tether::deck {

namespace {

SurfaceInteraction& current_interaction(DeckState& state) {
  return state.model.interactions[static_cast<std::size_t>(state.interaction)];
}

/// The surface `token` names; InputError naming the role otherwise.
const Surface& surface_named(const DeckState& state, const std::string& token, const SourceLocation& at,
                             const std::string& role) {
  const auto it = state.model.surfaces.find(to_upper(token));
  if (it == state.model.surfaces.end())
    throw InputError(at, "undefined " + role + " surface '" + token + "': expected a surface defined by *SURFACE");
  return it->second;
}

/// PRESSURE-OVERCLOSURE=LINEAR in the calculix dialect: CalculiX's data line
/// `K, sigma_inf, c0`, each optional; a value <= 0 (or missing) takes
/// CalculiX's default (K = 50 E and sigma_inf = E/70000 with E of the first
/// material, set by the analysis; c0 = 1e-3), with a warning for K as
/// CalculiX gives one.
void read_calculix_linear(DeckState& state, const KeywordBlock& block, PressureOverclosure& b) {
  b = PressureOverclosure{};
  b.law = PressureOverclosure::Law::Linear;
  b.meaning = Dialect::Calculix;
  const SourceLocation at = block.data.empty() ? block.where : block.data.front().where();
  if (block.data.size() > 1) throw InputError(block.data[1].where(), "LINEAR takes one data line 'K, sigma_inf, c0'");
  std::vector<double> r;  // by position: an empty field is 0 (CalculiX's default)
  if (!block.data.empty())
    for (const std::string& f : split_data_line(block.data.front().text).fields)
      r.push_back(f.empty() ? 0.0 : parse_real(f, at, "*SURFACE BEHAVIOR value"));
  while (!r.empty() && r.back() == 0.0) r.pop_back();
  if (r.size() > 3) throw InputError(at, "LINEAR: expected 'K, sigma_inf, c0' (three values at most)");
  const auto field = [&](std::size_t i) { return i < r.size() ? r[i] : 0.0; };
  b.stiffness = std::max(field(0), 0.0);
  b.sigma_inf = std::max(field(1), 0.0);
  b.reach_factor = field(2) > 0 ? field(2) : 1e-3;
  if (b.stiffness == 0)
    state.warn(at, "LINEAR: no slope K > 0 given; CalculiX's default K = 50 E (E of the first material) is used");
}

const std::vector<std::string_view> kContactVariables = {"CSTR", "CDIS", "CSTRESS", "CDISP", "CFN", "CFS", "CELS"};

}  // namespace

void handle_surface_interaction(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  SurfaceInteraction si;
  si.name = params.name("NAME");
  si.where = block.where;
  for (const auto& other : state.model.interactions)
    if (other.name == si.name)
      throw InputError(block.where, "*SURFACE INTERACTION " + si.name + " is defined twice (first at " +
                                        other.where.str() + ")");
  state.model.interactions.push_back(std::move(si));
  state.interaction = static_cast<int>(state.model.interactions.size()) - 1;
}

void handle_surface_behavior(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  PressureOverclosure& b = current_interaction(state).behavior;
  const std::string law = params.name("PRESSURE-OVERCLOSURE");
  std::vector<std::vector<double>> rows;
  for (const DataLine& line : block.data) {
    std::vector<double> row;
    for (const std::string& f : split_data_line(line.text).fields)
      if (!f.empty()) row.push_back(parse_real(f, line.where(), "*SURFACE BEHAVIOR value"));
    rows.push_back(std::move(row));
  }
  const SourceLocation at = block.data.empty() ? block.where : block.data.front().where();
  const bool enforcement_given = params.given("ENFORCEMENT") || params.given("EPSILON") || params.given("PENALTY") ||
                                 params.given("TOLERANCE");
  if (law == "HARD") {
    b = PressureOverclosure{};
    Enforcement& e = b.enforcement;
    const std::string method = params.name("ENFORCEMENT");
    if (method == "PENALTY") e.method = Enforcement::Method::Penalty;
    if (method == "AUGMENTED") e.method = Enforcement::Method::Augmented;
    e.epsilon = params.real("EPSILON");
    e.penalty = params.real("PENALTY");
    e.tolerance = params.real("TOLERANCE");
    if (e.epsilon < 0) throw InputError(block.where, "EPSILON must be >= 0 (a regularisation, length per force)");
    if (e.tolerance < 0) throw InputError(block.where, "TOLERANCE must be >= 0 (a penetration)");
    if (e.method != Enforcement::Method::Lagrange && !(e.penalty > 0))
      throw InputError(block.where, "ENFORCEMENT=" + method + " needs PENALTY=rho > 0 (force per unit overclosure)");
    if (params.given("EPSILON") && e.method != Enforcement::Method::Lagrange)
      throw InputError(block.where, "EPSILON applies to ENFORCEMENT=LAGRANGE only");
    if (state.model.dialect == Dialect::Calculix && e.method == Enforcement::Method::Lagrange)
      state.warn(block.where, "PRESSURE-OVERCLOSURE=HARD is enforced exactly (Lagrange multipliers) in the calculix "
                              "dialect too; CalculiX itself turns it into its LINEAR penalty law (K = 50 E, sigma_inf "
                              "= E/70000), so its results show a small penetration that tether's do not");
    return;
  }
  if (enforcement_given)
    throw InputError(block.where, "ENFORCEMENT, EPSILON, PENALTY and TOLERANCE apply to PRESSURE-OVERCLOSURE=HARD "
                                  "only; PRESSURE-OVERCLOSURE=" + law + " is already a penalty law");
  if (law == "LINEAR" && state.model.dialect == Dialect::Calculix) {
    read_calculix_linear(state, block, b);
    return;
  }
  if (rows.empty()) throw InputError(block.where, "PRESSURE-OVERCLOSURE=" + law + " needs a data line");
  if (law == "LINEAR") {
    b.law = PressureOverclosure::Law::Linear;
    b.meaning = Dialect::Abaqus;
    const auto& r = rows.front();
    b.stiffness = r.at(0);
    if (r.size() > 1)
      throw InputError(at, "LINEAR takes the slope K only in the abaqus dialect (p = K h); a second and third "
                           "field are CalculiX's sigma_inf and c0 (a smooth law with a small tension at open gaps, "
                           "c0 not an offset): read the deck with --dialect calculix for CalculiX's law, or give "
                           "`K` alone");
    if (!(b.stiffness > 0)) throw InputError(at, "LINEAR: the slope K must be > 0 (pressure per unit overclosure)");
  } else if (law == "EXPONENTIAL") {
    b.law = PressureOverclosure::Law::Exponential;
    const auto& r = rows.front();
    if (r.size() < 2) throw InputError(at, "EXPONENTIAL needs 'c0, p0' (clearance where pressure starts, pressure "
                                           "at zero clearance)");
    b.c0 = r[0];
    b.p0 = r[1];
    b.meaning = state.model.dialect;
    if (!(b.c0 > 0) || !(b.p0 > 0)) throw InputError(at, "EXPONENTIAL: c0 and p0 must be > 0");
  } else {  // TABULAR
    b.law = PressureOverclosure::Law::Tabular;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& r = rows[k];
      const SourceLocation line = block.data[k].where();
      if (r.size() % 2 != 0) throw InputError(line, "TABULAR: expected pairs 'pressure, overclosure'");
      for (std::size_t i = 0; i < r.size(); i += 2) b.table.emplace_back(r[i], r[i + 1]);
    }
    for (std::size_t i = 0; i < b.table.size(); ++i) {
      const SourceLocation line = block.data.back().where();
      if (b.table[i].first < 0) throw InputError(line, "TABULAR: pressures must be >= 0");
      if (i > 0 && !(b.table[i].second > b.table[i - 1].second))
        throw InputError(line, "TABULAR: overclosures must increase strictly");
      if (i > 0 && b.table[i].first < b.table[i - 1].first)
        throw InputError(line, "TABULAR: pressure must not decrease with overclosure");
    }
    if (b.table.size() < 2) throw InputError(at, "TABULAR needs at least two (pressure, overclosure) pairs");
  }
}

void handle_friction(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (block.data.empty()) throw InputError(block.where, "*FRICTION needs a data line 'mu[, stick slope]'");
  const DataLine& line = block.data.front();
  const auto f = split_data_line(line.text).fields;
  FrictionData friction;
  friction.mu = parse_real(f.at(0), line.where(), "friction coefficient mu");
  if (f.size() > 1 && !f[1].empty()) friction.stick_slope = parse_real(f[1], line.where(), "stick slope");
  friction.elastic_slip = params.real("ELASTIC SLIP");
  if (friction.mu < 0) throw InputError(line.where(), "friction coefficient " + f[0] + ": expected mu >= 0");
  if (friction.stick_slope < 0) throw InputError(line.where(), "stick slope must be >= 0");
  if (friction.elastic_slip < 0) throw InputError(block.where, "ELASTIC SLIP must be >= 0");
  current_interaction(state).friction = friction;
}

void handle_contact_pair(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const std::string interaction = params.name("INTERACTION");
  const bool known = std::any_of(state.model.interactions.begin(), state.model.interactions.end(),
                                 [&](const SurfaceInteraction& s) { return s.name == interaction; });
  if (!known)
    throw InputError(block.where, "undefined INTERACTION=" + interaction +
                                      ": expected the name of a *SURFACE INTERACTION");
  const std::string type = params.name("TYPE");
  if (type == "LINMORTAR" || type == "PGMORTAR" || type == "PGLINMORTAR")
    throw InputError(block.where, "TYPE=" + type + " (a CalculiX mortar variant) is not modelled: TYPE=MORTAR or "
                                  "SURFACE TO SURFACE selects tether's mortar contact (dual multipliers)");
  const bool mortar = type == "SURFACE TO SURFACE" || type == "MORTAR";
  if (mortar && params.given("SMOOTH"))
    throw InputError(block.where, "SMOOTH applies to TYPE=NODE TO SURFACE only: mortar contact integrates the "
                                  "master faces as they are");
  if (mortar && params.given("SMALL SLIDING"))
    state.warn(block.where, "SMALL SLIDING with TYPE=" + type + ": tether's mortar contact recomputes the "
                            "segmentation at every iteration (finite sliding), which includes small sliding");
  if (block.data.empty()) throw InputError(block.where, "*CONTACT PAIR needs a data line 'slave surface, master surface'");
  for (const DataLine& line : block.data) {
    const auto f = split_data_line(line.text).fields;
    if (f.size() != 2) throw InputError(line.where(), "expected 'slave surface, master surface'");
    ContactPairData pair;
    pair.where = line.where();
    pair.interaction = interaction;
    pair.slave = surface_named(state, f[0], pair.where, "slave").name;
    const Surface& master = surface_named(state, f[1], pair.where, "master");
    if (master.kind != Surface::Kind::ElementFaces)
      throw InputError(pair.where, "master surface '" + f[1] + "' must be made of element faces (TYPE=ELEMENT)");
    if (to_upper(f[0]) == to_upper(f[1])) throw InputError(pair.where, "the slave and master surfaces are the same");
    pair.master = master.name;
    if (mortar && surface_named(state, f[0], pair.where, "slave").kind != Surface::Kind::ElementFaces)
      throw InputError(pair.where, "slave surface '" + f[0] + "' is node-based: mortar contact (TYPE=" + type +
                                       ") integrates over the slave faces and needs a surface of element faces");
    pair.node_to_surface = !mortar;
    pair.small_sliding = params.given("SMALL SLIDING") && !mortar;
    if (params.given("ADJUST")) {
      pair.adjust = params.real("ADJUST");
      if (pair.adjust < 0) throw InputError(block.where, "ADJUST must be a clearance >= 0");
    }
    if (params.given("SMOOTH")) {
      pair.smoothing = params.real("SMOOTH");
      if (!(pair.smoothing >= 0 && pair.smoothing <= kMaxSmoothing))
        throw InputError(block.where, "SMOOTH=" + params.text("SMOOTH") +
                                          ": expected a fraction of the master faces 0 < s <= 0.5 (0: no smoothing)");
      for (const ElementFace& face : master.faces) {
        const Element& e = state.model.elements[static_cast<std::size_t>(face.element)];
        const auto local = face_nodes(e.type.shape, face.face);
        if (std::count_if(local.begin(), local.end(), [](int n) { return n >= 0; }) > 2 && pair.smoothing > 0)
          throw InputError(pair.where, "SMOOTH applies to linear (2-node) master faces only: master surface '" +
                                            f[1] + "' has quadratic faces, which are already curved (element " +
                                            label_text(state.model.instances, e.id) + ")");
      }
    }
    state.model.contact_pairs.push_back(std::move(pair));
  }
}

void handle_contact_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  // *CONTACT OUTPUT inside an *OUTPUT block writes on the block's schedule unless it gives FREQUENCY.
  const bool in_block = block.keyword == "CONTACT OUTPUT" && state.output_active && !params.given("FREQUENCY");
  OutputRequest r = in_block ? state.output_schedule : OutputRequest{};
  r.kind = block.keyword == "CONTACT PRINT" ? OutputRequest::Kind::ContactPrint : OutputRequest::Kind::ContactFile;
  r.where = block.where;
  if (params.given("SET")) {  // *CONTACT PRINT only: CalculiX's test deck thread.inp writes it
    if (state.model.dialect != Dialect::Calculix)
      throw InputError(block.where, "*CONTACT PRINT has no parameter SET (its rows are all slave nodes of all "
                                    "pairs); ccx warns and ignores it: so does the calculix dialect");
    state.warn(block.where, "SET=" + params.text("SET") + " on *CONTACT PRINT is ignored, as ccx does: the rows "
                            "are all slave nodes of all contact pairs");
  }
  if (!in_block) r.frequency = params.integer("FREQUENCY"), r.schedule_given = params.given("FREQUENCY");
  if (r.frequency < 0) throw InputError(block.where, "FREQUENCY must be >= 0");
  if (r.kind == OutputRequest::Kind::ContactPrint && params.given("FREQUENCY")) note_print_frequency(state, r.frequency);
  for (const DataLine& line : block.data)
    for (const std::string& f : split_data_line(line.text).fields) {
      const std::string v = to_upper(f);
      if (v.empty()) continue;
      if (std::find(kContactVariables.begin(), kContactVariables.end(), v) == kContactVariables.end()) {
        state.warn(line.where(), "contact output variable " + v + " is not available and is ignored (available: "
                                 "CSTR, CDIS, CSTRESS, CDISP, CFN, CFS, CELS)");
        continue;
      }
      if (v == "CELS")
        state.warn(line.where(), "contact output variable CELS (contact elastic energy) is not computed by tether "
                                 "and is not written");
      r.variables.push_back(v);
    }
  if (r.variables.empty()) r.variables = {"CSTR", "CDIS"};
  state.step().outputs.push_back(std::move(r));
  if (state.step().outputs.back().kind == OutputRequest::Kind::ContactPrint)
    state.print_requests.push_back(state.step().outputs.size() - 1);
}

void apply_contact_adjustments(DeckState& state) {
  Model& model = state.model;
  for (const ContactPairData& pair : model.contact_pairs) {
    if (!(pair.adjust > 0)) continue;
    const Surface& master = model.surfaces.at(pair.master);
    const Surface& slave = model.surfaces.at(pair.slave);
    std::vector<std::vector<int>> faces;
    double longest = 0;
    for (const ElementFace& f : master.faces) {
      const Element& e = model.elements[static_cast<std::size_t>(f.element)];
      std::vector<int> nodes;
      for (int local : face_nodes(e.type.shape, f.face))
        if (local >= 0) nodes.push_back(e.nodes[static_cast<std::size_t>(local)]);
      longest = std::max(longest, (model.coords[static_cast<std::size_t>(nodes[1])] -
                                   model.coords[static_cast<std::size_t>(nodes[0])]).norm());
      faces.push_back(std::move(nodes));
    }
    std::vector<int> slave_nodes = slave.nodes;
    for (const ElementFace& f : slave.faces) {
      const Element& e = model.elements[static_cast<std::size_t>(f.element)];
      for (int local : face_nodes(e.type.shape, f.face))
        if (local >= 0) slave_nodes.push_back(e.nodes[static_cast<std::size_t>(local)]);
    }
    std::sort(slave_nodes.begin(), slave_nodes.end());
    slave_nodes.erase(std::unique(slave_nodes.begin(), slave_nodes.end()), slave_nodes.end());
    // Onto the surface the analysis will see: the faces, or the smoothed surface.
    const MasterSegments segments(faces, pair.smoothing);
    const MasterSurface& surface = segments.surface();
    std::vector<Eigen::Vector2d> surface_points;
    segments.point_positions(model.coords, surface_points);
    std::vector<Eigen::Vector2d> points;
    for (int n : slave_nodes) points.push_back(model.coords[static_cast<std::size_t>(n)]);
    SearchOptions options;
    options.search_radius = 2 * longest + pair.adjust;
    const std::vector<ContactPairing> pairings = find_closest(surface, surface_points, points, options);
    int moved = 0;
    double largest = 0;
    for (std::size_t i = 0; i < slave_nodes.size(); ++i) {
      const ContactPairing& p = pairings[i];
      // Nodes within the clearance (and overclosed ones) move onto the surface
      // along its normal; corner and open-end pairings have no normal: left alone.
      if (!p.found() || p.at_corner || p.gap > pair.adjust) continue;
      std::vector<Eigen::Vector2d> y;
      for (int n : surface.segment_nodes(p.segment)) y.push_back(surface_points[static_cast<std::size_t>(n)]);
      const SegmentGeometry g = segment_geometry(points[i], y, ContactDerivatives::none);
      model.coords[static_cast<std::size_t>(slave_nodes[i])] = g.point;
      largest = std::max(largest, std::abs(g.gap));
      ++moved;
    }
    state.warn(pair.where, "ADJUST=" + std::to_string(pair.adjust) + " moved " + std::to_string(moved) +
                               " slave node(s) of " + pair.slave + " onto " + pair.master +
                               " (stress-free; largest move " + std::to_string(largest) + ")");
  }
}

void warn_about_stiff_slaves(DeckState& state) {
  const Model& model = state.model;
  // The stiffest material among the elements of a surface's faces [stress]; 0 for a node surface.
  const auto modulus = [&](const Surface& surface) {
    double most = 0;
    for (const ElementFace& f : surface.faces) {
      const Element& e = model.elements[static_cast<std::size_t>(f.element)];
      if (e.section < 0) continue;
      const SolidSection& section = model.sections[static_cast<std::size_t>(e.section)];
      most = std::max(most, model.materials[static_cast<std::size_t>(section.material)].modulus());
    }
    return most;
  };
  for (const ContactPairData& pair : model.contact_pairs) {
    const double slave = modulus(model.surfaces.at(pair.slave)), master = modulus(model.surfaces.at(pair.master));
    if (!(master > 0) || slave < kStiffSlaveRatio * master) continue;
    state.warn(pair.where, "the slave surface " + pair.slave + " belongs to a body " +
                               format_number(slave / master) + " times stiffer than the master surface " +
                               pair.master + " (E " + format_number(slave) + " against " + format_number(master) +
                               "): the stiffer body should be the master (ABAQUS's advice too); a stiff slave "
                               "over-constrains node-to-surface contact and Newton may need many more iterations "
                               "or stop. Swap them on the data line: " + pair.master + ", " + pair.slave);
  }
}

}  // namespace tether::deck
