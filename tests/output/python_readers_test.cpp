// Independent readers: the .vtu/.pvd files are read back with meshio and the
// .dat with a small CalculiX .dat parser (which also reads a real ccx file).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "output/tiny_model.hpp"
#include "tether/output/result_writer.hpp"

namespace tether {
namespace {

using test::fresh_directory;
using test::synthetic_results;
using test::tiny_model;

const std::string kScripts = std::string(TETHER_SOURCE_DIR) + "/tests/output/";

std::string shell_quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

/// Minimal JSON text builder for the expectation files.
class Json {
 public:
  Json() { out_.precision(17); }
  std::ostringstream& out() { return out_; }
  template <class Range, class Fn>
  void list(const Range& range, Fn item) {
    out_ << '[';
    bool first = true;
    for (const auto& x : range) {
      if (!first) out_ << ',';
      first = false;
      item(x);
    }
    out_ << ']';
  }
  void numbers(std::initializer_list<double> values) {
    list(values, [this](double v) { out_ << v; });
  }
  void write(const std::filesystem::path& file) const { std::ofstream(file) << out_.str(); }

 private:
  std::ostringstream out_;
};

const char* meshio_type(Shape s) {
  switch (s) {
    case Shape::Tri3: return "triangle";
    case Shape::Quad4: return "quad";
    case Shape::Tri6: return "triangle6";
    case Shape::Quad8: return "quad8";
  }
  return "?";
}

double mises(double a, double b, double c, double d) {
  return std::sqrt(0.5 * ((a - b) * (a - b) + (b - c) * (b - c) + (c - a) * (c - a)) + 3 * d * d);
}

struct Increment {
  int number;
  double time;
  double factor;
};

std::vector<MultiplierValues> some_multipliers() {
  return {{"EQUATION 1", {0, 4}, {2.5}, {0.0}, {{0, {-2.5, 0.0}}, {4, {2.5, 0.0}}}},
          {"CONTACT 19", {4, 5}, {1.0, -3.0}, {0.0, 0.0}, {{4, {0.0, -1.0}}, {5, {3.0, 1.0}}}}};
}

/// Expected content of every .vtu, from the formulas in tiny_model.hpp.
void write_vtu_expectation(const Model& m, const std::vector<Increment>& increments, const std::string& job,
                           const std::filesystem::path& file) {
  Json j;
  auto& o = j.out();
  o << "{\"points\":";
  j.list(m.coords, [&](const Eigen::Vector2d& x) { j.numbers({x.x(), x.y(), 0.0}); });
  o << ",\"node_ids\":";
  j.list(m.node_ids, [&](int id) { o << id; });
  o << ",\"cells\":";
  j.list(m.elements, [&](const Element& e) {
    o << "{\"type\":\"" << meshio_type(e.type.shape) << "\",\"id\":" << e.id << ",\"nodes\":";
    j.list(e.nodes, [&](int n) { o << n; });
    o << '}';
  });
  o << ",\"increments\":";
  j.list(increments, [&](const Increment& inc) {
    const double f = inc.factor;
    std::vector<int> nodes(static_cast<std::size_t>(m.n_nodes()));
    for (int i = 0; i < m.n_nodes(); ++i) nodes[static_cast<std::size_t>(i)] = i;
    const auto x = [&](int i) { return m.coords[static_cast<std::size_t>(i)].x(); };
    const auto y = [&](int i) { return m.coords[static_cast<std::size_t>(i)].y(); };
    const auto L = [&](int i) { return static_cast<double>(m.node_ids[static_cast<std::size_t>(i)]); };
    o << "{\"file\":\"" << job << "_1_" << inc.number << ".vtu\",\"time\":" << inc.time << ",\"U\":";
    j.list(nodes, [&](int i) { j.numbers({f * (1e-3 * x(i) + 1e-6 * L(i)), f * (-2e-3 * y(i)), 0.0}); });
    o << ",\"RF\":";
    j.list(nodes, [&](int i) { j.numbers({f * L(i), -f * L(i) / 2, 0.0}); });
    o << ",\"S\":";
    j.list(nodes, [&](int i) { j.numbers({f * 100 * x(i), f * 200 * y(i), f * 30 * (x(i) + y(i)), f * 10 * x(i) * y(i), 0, 0}); });
    o << ",\"E\":";
    j.list(nodes, [&](int i) {
      j.numbers({1e-5 * f * 100 * x(i), 1e-5 * f * 200 * y(i), 1e-5 * f * 30 * (x(i) + y(i)), 1e-5 * f * 10 * x(i) * y(i), 0, 0});
    });
    o << ",\"S_Mises\":";
    j.list(nodes, [&](int i) { o << mises(f * 100 * x(i), f * 200 * y(i), f * 30 * (x(i) + y(i)), f * 10 * x(i) * y(i)); });
    o << ",\"LAGRANGE_MULTIPLIER\":";
    // Single-equation owners only (EQUATION 1 on nodes 0 and 4); CONTACT 19 has two equations.
    j.list(nodes, [&](int i) { o << (i == 0 || i == 4 ? 2.5 : 0.0); });
    o << ",\"CONSTRAINT_FORCE\":";
    j.list(nodes, [&](int i) {
      if (i == 0) j.numbers({-2.5, 0.0, 0.0});
      else if (i == 4) j.numbers({2.5, -1.0, 0.0});
      else if (i == 5) j.numbers({3.0, 1.0, 0.0});
      else j.numbers({0.0, 0.0, 0.0});
    });
    o << ",\"cell_S\":";
    j.list(m.elements, [&](const Element& e) {
      const double h = (test::n_points(e.type.shape) - 1) / 2.0;  // mean of k
      j.numbers({f * (e.id + h), -f * h, f * h / 2, f * (e.id / 100.0 + 2 * h), 0, 0});
    });
    o << '}';
  });
  o << '}';
  j.write(file);
}

void run_vtu_round_trip(VtuEncoding encoding, const std::string& name) {
  if (!test::python_with_meshio_available())
    GTEST_SKIP() << "/usr/bin/python3 with meshio and numpy (Debian python3-meshio, python3-numpy) is not "
                    "installed; the independent VTU reader check is skipped";
  const Model model = tiny_model();
  const auto dir = fresh_directory(name);
  const std::vector<Increment> increments{{1, 0.25, 0.25}, {2, 0.5, 0.5}, {3, 1.0, 1.0}};
  {
    ResultWriter writer(model, dir, "job", {encoding, true});
    for (const auto& inc : increments) {
      auto results = synthetic_results(model, 1, inc.number, inc.time, inc.factor);
      results.multipliers = some_multipliers();
      writer.write_increment(results, {}, inc.number == 3);
    }
  }
  write_vtu_expectation(model, increments, "job", dir / "expected.json");
  EXPECT_EQ(test::run_python(shell_quoted(kScripts + "read_vtu.py") + " " + shell_quoted(dir / "job.pvd") + " " +
                             shell_quoted(dir / "expected.json")),
            0);
  EXPECT_EQ(test::count_temporary_files(dir), 0);
  // VTK's own reader (ParaView's) when Debian's python3-vtk9 is installed: status 3 = not installed.
  const int vtk_status = test::run_python(shell_quoted(kScripts + "read_vtu_vtk.py") + " " +
                                          shell_quoted(dir / "job.pvd") + " " + shell_quoted(dir / "expected.json"));
  if (vtk_status == 3)
    std::cout << "[ NOTE     ] python3-vtk9 is not installed: VTK's own reader check skipped\n";
  else
    EXPECT_EQ(vtk_status, 0);
}

TEST(PythonReaders, MeshioReadsBase64VtuAndPvd) { run_vtu_round_trip(VtuEncoding::Base64, "meshio_base64"); }

TEST(PythonReaders, MeshioReadsAsciiVtuAndPvd) { run_vtu_round_trip(VtuEncoding::Ascii, "meshio_ascii"); }

TEST(PythonReaders, MeshioCheckFailsOnWrongValues) {
  if (!test::python_with_meshio_available()) GTEST_SKIP() << "/usr/bin/python3 with meshio is not installed";
  const Model model = tiny_model();
  const auto dir = fresh_directory("meshio_wrong");
  {
    ResultWriter writer(model, dir, "job");
    auto results = synthetic_results(model, 1, 1, 1.0, 1.0);
    results.multipliers = some_multipliers();
    results.displacement[7].y() += 1e-9;
    writer.write_increment(results, {}, true);
  }
  write_vtu_expectation(model, {{1, 1.0, 1.0}}, "job", dir / "expected.json");
  EXPECT_EQ(test::run_python(shell_quoted(kScripts + "read_vtu.py") + " " + shell_quoted(dir / "job.pvd") + " " +
                             shell_quoted(dir / "expected.json") + " 2> /dev/null"),
            1);
}

bool python_available() { return std::filesystem::exists("/usr/bin/python3"); }

TEST(PythonReaders, DatParserReadsCalculixOutput) {
  if (!python_available()) GTEST_SKIP() << "/usr/bin/python3 is not installed";
  EXPECT_EQ(test::run_python(shell_quoted(kScripts + "check_datfile.py") + " " + shell_quoted(kScripts + "data/ccx220_two_cpe4.dat") +
                             " " + shell_quoted(kScripts + "data/ccx220_two_cpe4.json")),
            0);
}

TEST(PythonReaders, DatParserReadsTetherOutput) {
  if (!python_available()) GTEST_SKIP() << "/usr/bin/python3 is not installed";
  const Model model = tiny_model();
  const auto dir = fresh_directory("dat_parser");
  OutputRequest u{OutputRequest::Kind::NodePrint, "LEFT", {"U", "RF"}, 1, true, false, {}};
  OutputRequest s{OutputRequest::Kind::ElementPrint, "", {"S", "E"}, 2, false, false, {}};
  {
    ResultWriter writer(model, dir, "job");
    writer.write_increment(synthetic_results(model, 1, 1, 0.5, 0.5), {u, s}, false);
    writer.write_increment(synthetic_results(model, 1, 2, 1.0, 1.0), {u, s}, true);
  }
  Json j;
  auto& o = j.out();
  const std::vector<int> left{0, 3, 11};
  std::vector<std::pair<double, double>> increments{{0.5, 0.5}, {1.0, 1.0}};
  o << '[';
  for (const auto& [time, f] : increments) {
    const auto header = [&](const char* title, const char* set) {
      o << "{\"title\":\"" << title << "\",\"set\":\"" << set << "\",\"time\":" << time << ",\"rows\":";
    };
    header("displacements (vx,vy,vz)", "LEFT");
    j.list(left, [&](int i) {
      const double x = model.coords[i].x(), y = model.coords[i].y(), L = model.node_ids[i];
      j.numbers({L, f * (1e-3 * x + 1e-6 * L), f * -2e-3 * y, 0});
    });
    o << "},";
    header("forces (fx,fy,fz)", "LEFT");
    j.list(left, [&](int i) { j.numbers({double(model.node_ids[i]), f * model.node_ids[i], -f * model.node_ids[i] / 2, 0}); });
    o << "},";
    header("total force (fx,fy,fz)", "LEFT");
    o << '[';
    j.numbers({f * 47, -f * 23.5, 0});
    o << "]}";
    if (time == 1.0) {  // EL PRINT has FREQUENCY=2: increment 2 only
      for (const bool stress : {true, false}) {
        o << ',';
        header(stress ? "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)"
                      : "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)",
               "EALL");
        o << '[';
        bool first = true;
        for (const auto& e : model.elements)
          for (int k = 0; k < test::n_points(e.type.shape); ++k) {
            if (!first) o << ',';
            first = false;
            const double c = stress ? 1.0 : 1e-6;
            j.numbers({double(e.id), k + 1.0, c * f * (e.id + k), -c * f * k, c * f * k / 2, c * f * (e.id / 100.0 + 2 * k), 0, 0});
          }
        o << "]}";
      }
    }
    if (time != 1.0) o << ',';
  }
  o << ']';
  j.write(dir / "expected.json");
  EXPECT_EQ(test::run_python(shell_quoted(kScripts + "check_datfile.py") + " " + shell_quoted(dir / "job.dat") + " " +
                             shell_quoted(dir / "expected.json")),
            0);
}

}  // namespace
}  // namespace tether
