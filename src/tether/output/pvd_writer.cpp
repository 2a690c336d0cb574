#include "tether/output/pvd_writer.hpp"

#include <fmt/format.h>

#include <bit>
#include <iterator>

#include "tether/output/atomic_file.hpp"
#include "tether/output/xml_text.hpp"

namespace tether {

PvdWriter::PvdWriter(std::filesystem::path file) : file_(std::move(file)) {}

void PvdWriter::add(double total_time, const std::string& relative_file) {
  entries_.push_back({total_time, relative_file});
  std::string text = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"{}\">\n"
      "  <Collection>\n",
      std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian");
  for (const auto& e : entries_)
    fmt::format_to(std::back_inserter(text), "    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                   e.time, xml_escape(e.file));
  text += "  </Collection>\n</VTKFile>\n";
  AtomicFile atomic(file_);
  atomic.stream() << text;
  atomic.commit();
}

}  // namespace tether
