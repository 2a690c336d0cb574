#pragma once
/// \file Text report (`.dat`) in CalculiX's layout, for `*NODE PRINT` and
/// `*EL PRINT` requests, plus tether's constraint-multiplier blocks.

#include <filesystem>
#include <fstream>
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
/// the set's order (ascending index). NODE FILE / EL FILE requests are ignored.
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
///   selects a node set (tools/datfile.py `last_block(blocks,
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

class DatWriter {
 public:
  /// Creates (truncates) `file`. Throws std::runtime_error when it cannot.
  DatWriter(const Model& model, std::filesystem::path file);

  /// Throws InputError (at the request's deck line) when a print request
  /// names an unknown set or a variable this writer does not print
  /// (supported: NODE PRINT U, RF; EL PRINT S, E). Other kinds pass.
  static void check(const Model& model, const OutputRequest& request);

  /// Writes the print requests due at this increment (see is_due()), in the
  /// order given, then the multiplier blocks (always), and flushes. All requests are checked first, so a bad
  /// request writes nothing. Throws std::invalid_argument when a requested
  /// quantity is missing from `results` or sized wrongly for the mesh.
  void write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                       bool last_in_step);

  [[nodiscard]] const std::filesystem::path& file() const { return file_; }

 private:
  const Model& model_;
  std::filesystem::path file_;
  std::ofstream out_;
};

}  // namespace tether
