#include "tether/output/pretension_report.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tether/output/dat_writer.hpp"
#include "tether/output/fortran_format.hpp"

namespace tether {

BoltState bolt_state(const PretensionSection& section, const IncrementResults& results) {
  for (const MultiplierValues& m : results.multipliers) {
    if (m.owner != section.constraint) continue;
    for (const NodalConstraintForce& f : m.nodal_force)
      if (f.node == section.node)
        return {results.displacement[static_cast<std::size_t>(section.node)].x(), -f.force.x()};
  }
  throw std::invalid_argument("pretension section " + section.constraint +
                              ": the results hold no force of its equations on the pretension node");
}

void write_pretension_blocks(std::string& text, const Model& model, const IncrementResults& results) {
  const auto out = std::back_inserter(text);
  for (const PretensionSection& section : model.pretension_sections) {
    const BoltState s = bolt_state(section, results);
    fmt::format_to(out, "\n {} for set {} and time {:>14}\n\n", kPretensionTitle,
                   multiplier_set_name(section.constraint, 0), fortran_e(results.total_time, 7));
    fmt::format_to(out, "{:10d} {:13.6E} {:13.6E}\n", model.node_ids[static_cast<std::size_t>(section.node)],
                   s.tightening + 0.0, s.force + 0.0);
  }
}

}  // namespace tether
