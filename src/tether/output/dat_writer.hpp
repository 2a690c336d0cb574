#pragma once
/// \file Text report (`.dat`) in CalculiX's layout, for `*NODE PRINT` and
/// `*EL PRINT` requests.

#include <filesystem>
#include <fstream>
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
/// The Model must outlive the writer.
class DatWriter {
 public:
  /// Creates (truncates) `file`. Throws std::runtime_error when it cannot.
  DatWriter(const Model& model, std::filesystem::path file);

  /// Throws InputError (at the request's deck line) when a print request
  /// names an unknown set or a variable this writer does not print
  /// (supported: NODE PRINT U, RF; EL PRINT S, E). Other kinds pass.
  static void check(const Model& model, const OutputRequest& request);

  /// Writes the print requests due at this increment (see is_due()), in the
  /// order given, and flushes. All requests are checked first, so a bad
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
