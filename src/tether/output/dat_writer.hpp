#pragma once
/// \file Text report (`.dat`) in CalculiX's layout, for `*NODE PRINT`,
/// `*EL PRINT` and `*CONTACT PRINT` requests, plus tether's constraint-multiplier
/// and contact-state blocks.

#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tether/model/model.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// Writes print requests the way ccx 2.20 does, so one parser reads both
/// programs' files. Each block is a blank line, a header, a blank line and
/// rows, e.g.
///
///      displacements (vx,vy,vz) for set NALL and time  0.1000000E+01
///
///              5  1.234567E-05 -2.345678E-06  0.000000E+00
///
/// - `*NODE PRINT` U -> `displacements (vx,vy,vz)`, RF -> `forces (fx,fy,fz)`
///   (rows: label as I10, then 3 x (1X,E13.6)); with TOTALS=YES a
///   `total force (fx,fy,fz)` block follows (one row: 6X, 3 x (1X,E13.6)),
///   with TOTALS=ONLY it replaces the nodal rows.
/// - `*EL PRINT` S -> `stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)`,
///   E -> `strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)` (rows: label
///   I10, integration point I4, 6 x (1X,E13.6); tensor shear strains).
/// Times are total times as Fortran E14.7 (` 0.1000000E+01`). Labels are the
/// deck's node/element labels; z components (and sxz, syz) are 0. A request
/// without a set prints all nodes as NALL / all elements as EALL; rows follow
/// the set's order (ascending index). NODE FILE / EL FILE / CONTACT FILE
/// requests are ignored.
///
/// Constraint multipliers (tether's own block; ccx has none): every call of
/// write_increment() — i.e. every converged increment — whose results carry
/// multipliers appends, after the print requests, one block per constraint
/// with at least one multiplier, in the order of IncrementResults::multipliers:
///
///      constraint multipliers (constraint,equation,f,lambda) for set LINK-A and time  0.1000000E+01
///
///              1    1 -1.110223E-16  2.000000E+00
///
/// - the "set" is the constraint's name (MultiplierValues::owner) with every
///   blank replaced by `_` ("MPC-2 LINK" -> `MPC-2_LINK`; an empty name ->
///   `C<number>`), so a reader selects a constraint by name exactly as it
///   selects a node set (tools/tethertools/dat.py `last_block(blocks,
///   "constraint multipliers", "LINK-A")`);
/// - rows: constraint number (I10: 1-based position in the increment's list
///   of multiplier owners — built-in constraints in deck order, then user
///   constraints), equation number within the constraint (I5, 1-based), the
///   value of the constraint row f (E13.6; f - eps*lambda for a user routine)
///   and lambda (E13.6: the multiplier, or rho f / lambda_bar + rho f for
///   penalty / augmented enforcement). Every row is numeric, so CalculiX
///   .dat parsers read it unchanged.
/// Sign: the force the constraint exerts on dof i is -lambda df/du_i (for
/// LINK, lambda > 0 is tension). These blocks are not controlled by print
/// requests; a constraint whose user routine has no multipliers has none.
///
/// `*CONTACT PRINT` (FREQUENCY as for the other print requests; one result
/// entry per *CONTACT PAIR, IncrementResults::contact). The ccx blocks below
/// were checked against ccx 2.20 runs of 2D NODE TO SURFACE decks (CPE4
/// blocks pressed together, then slid with Coulomb friction, master face
/// horizontal with outward normal +y or -y, and vertical):
/// - CSTR / CSTRESS ->
///
///      contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.1000000E+01
///
///   (ccx: `... and time',e14.7` -- ONE blank before the time, unlike the set
///   blocks), rows label I10, 3 x (1X,E13.6): pressure (ContactNodeValues::
///   pressure, > 0 in compression), tang1, tang2 (shear stress, see below).
/// - CDIS / CDISP ->
///
///      relative contact displacement (slave node,normal,tang1,tang2) for all contact elements and time 0.1000000E+01
///
///   rows label, normal = the gap (ContactNodeValues::gap: ccx prints the
///   clearance, > 0 open, < 0 penetration -- NOT the overclosure), tang1,
///   tang2 = the accumulated relative tangential displacement (ccx: the total
///   since contact, signed, not the increment's): here the sum of the
///   increments' slip Δs (ContactNodeValues::slip) over all converged
///   increments in which the node was closed, summed by this writer (so every
///   converged increment must pass through write_increment(), once).
/// - Rows: as ccx, which prints only the slave nodes that have a contact
///   element at the end of the increment (an open slave node 5e-4 away on a
///   unit mesh is not printed): the slave nodes whose status is stick or slip,
///   pair after pair, in each pair's node order; labels are the deck's 2D
///   node labels (ccx prints its expanded 3D node numbers). One block for all
///   pairs, as ccx; no closed node: header only.
/// - tang1/tang2 follow ccx's local directions (springforc_n2f): for a master
///   face that is not vertical, tang1 is the in-plane master tangent with
///   POSITIVE x component and tang2 (out of plane) is 0; for a vertical face
///   (1 - |n_x| < 1.5231e-6) tang1 is out of plane (0) and tang2 = n x e3
///   (n = outward master normal). The shear along that direction has the
///   sign of the slave's slip relative to the master (ccx: tang1 > 0 when the
///   slave slides towards +tang1 -- the friction traction the slave exerts on
///   the master, minus the one acting on the slave). tether's
///   ContactNodeValues::shear has the same sign along its own tangent t (face
///   node 1 -> 2), so the writer prints shear * (t . tang) = +-shear. The
///   directions are evaluated on the current master face (coordinates +
///   displacement) at ξ*. Example: a master on top of a body (outward normal
///   +y) has t = -x, so tang1 = +x = -t.
/// - CFN / CFS: ccx 2.20 requires SLAVE=, MASTER= for them (tether's reader has
///   no such parameters) and for node-to-surface contact prints only zeros and
///   NaN (its `statistics for slave set ...` block is filled by surface-to-
///   surface contact only). tether writes its own blocks, one per pair:
///
///      total normal contact force (fx,fy,fz) for pair SLAVE-MASTER and time  0.1000000E+01
///
///              1.000000E+00 -2.000000E+02  0.000000E+00
///
///   CFN: sum of N n, CFS (`total shear contact force`): sum of -T t over the
///   pair's slave nodes (n, t of the current master face at ξ*) -- the forces
///   of the master on the slave body; their sum is
///   ContactPairValues::total_force. Row as ccx's `total force`: 6X,
///   3 x (1X,E13.6).
/// - CELS (elastic contact energy) is accepted and not written: the results
///   carry no contact energy (and HARD contact by multipliers stores none).
/// - Then, whenever at least one *CONTACT PRINT request is due, tether's own
///   block for every pair (all of its slave nodes, open ones too):
///
///      contact state (slave node,status,gap,pressure,shear,slip,total slip,master elem,master face,xi) for pair SLAVE-MASTER and time  0.1000000E+01
///
///              22    2 -1.000000E-09  1.500000E+02  3.000000E+01  2.000000E-04  5.000000E-04       101    1 -2.500000E-01
///
///   rows: slave node label I10, status I5 (0 open, 1 stick, 2 slip; closed
///   frictionless is slip), gap, pressure, shear (T/area, along the master
///   tangent t from face node 1 to 2, with the sign of the slip), slip (Δs of
///   this increment along t), total slip (sum of |Δs| over slipping
///   increments), each 1X,E13.6, master element label I10 (0: not paired),
///   master face number I5 (S1 = 1), ξ* (1X,E13.6, face_nodes() order). All
///   numeric, so .dat parsers read it. A node-based slave surface has no
///   tributary area: its block is titled kNodeBasedContactStateTitle, and
///   pressure and shear are the node's forces divided by its area from
///   *SURFACE, TYPE=NODE (default 1, as in ABAQUS: then the forces).
///   The pair's name (contact_pair_set_name()) is `SLAVE-MASTER` from the
///   k-th *CONTACT PAIR of the model (its slave and master surface names), so
///   tools/tethertools/dat.py's `last_block(blocks, "contact state", "SLAVE-MASTER")`
///   selects it. One block per variable and pair (several *CONTACT PRINT due
///   at one increment: still one state block per pair).
/// Blocks follow the order of the requests and of their variables; the
/// contact-state blocks come after all requests, the multiplier blocks last.
/// A model without contact pairs prints CSTR/CDIS headers without rows and no
/// CFN/CFS/state blocks.
///
/// The Model must outlive the writer.
/// Title of the multiplier blocks (see DatWriter).
inline constexpr std::string_view kMultiplierTitle = "constraint multipliers (constraint,equation,f,lambda)";

/// The "set" token of a constraint's multiplier block: `owner` with blanks
/// replaced by `_`, or `C<number>` when it is empty.
std::string multiplier_set_name(const std::string& owner, int number);

/// Appends the multiplier blocks of one increment (layout: see DatWriter).
/// Throws std::invalid_argument when an owner has different numbers of values
/// of lambda and f.
void write_multiplier_blocks(std::string& text, const std::vector<MultiplierValues>& multipliers, double time);

/// Title of tether's contact-state blocks (see DatWriter).
inline constexpr std::string_view kContactStateTitle =
    "contact state (slave node,status,gap,pressure,shear,slip,total slip,master elem,master face,xi)";
/// The same for a node-based slave surface, whose pressure and shear are
/// force / node area (the area its *SURFACE line gives, default 1).
inline constexpr std::string_view kNodeBasedContactStateTitle =
    "contact state (slave node,status,gap,force/node area,shear force/node area,slip,total slip,master elem,"
    "master face,xi)";

/// The name printed for the k-th entry (0-based) of IncrementResults::contact:
/// `SLAVE-MASTER` from model.contact_pairs[k] when the model has that pair,
/// else ContactPairValues::name with blanks replaced by `_` (`P<k+1>` when
/// empty).
std::string contact_pair_set_name(const Model& model, const std::vector<ContactPairValues>& contact,
                                  std::size_t k);

/// Appends the contact-state blocks of one increment (layout: see DatWriter).
/// Throws std::invalid_argument when a slave node index is outside the mesh.
void write_contact_state_blocks(std::string& text, const Model& model, const std::vector<ContactPairValues>& contact,
                                double time);

/// Per contact pair, per slave node index: the accumulated slip CDIS prints.
using RelativeSlip = std::vector<std::map<int, double>>;

class DatWriter {
 public:
  /// Creates (truncates) `file`. Throws std::runtime_error when it cannot.
  DatWriter(const Model& model, std::filesystem::path file);

  /// Throws InputError (at the request's deck line) when a print request
  /// names an unknown set or a variable this writer does not print
  /// (supported: NODE PRINT U, RF, V, A; EL PRINT S, E; CONTACT PRINT CSTR, CDIS,
  /// CSTRESS, CDISP, CFN, CFS, CELS). Other kinds pass.
  static void check(const Model& model, const OutputRequest& request);

  /// Writes the print requests due at this increment (see is_due()), in the
  /// order given, then the contact-state blocks (when a *CONTACT PRINT is
  /// due), then the multiplier blocks (always), then the energies (dynamic
  /// steps: when a print request is due, and at the step's end), and flushes. All requests are
  /// checked first, so a bad request writes nothing. Throws
  /// std::invalid_argument when a requested quantity is missing from `results`
  /// or sized wrongly for the mesh, or a contact node is paired with an
  /// element face the model does not have. Call it once for every converged
  /// increment, in order: it sums the slip printed by CDIS.
  void write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                       bool last_in_step);

  [[nodiscard]] const std::filesystem::path& file() const { return file_; }

  /// Restart: appends the history this writer keeps between increments (the
  /// CDIS slip sums) to `out`, so that a restarted run prints what an
  /// uninterrupted one would.
  void save_state(std::vector<double>& out) const;
  /// Restart: restores what save_state() wrote (all of `in`); std::runtime_error
  /// when `in` is not such a state for this model.
  void load_state(std::span<const double> in);

 private:
  const Model& model_;
  std::filesystem::path file_;
  std::ofstream out_;
  /// Per pair, per slave node index: sum of Δs along ccx's in-plane tangent
  /// over the closed increments written so far (CDIS tang1/tang2).
  RelativeSlip relative_slip_;
};

}  // namespace tether
