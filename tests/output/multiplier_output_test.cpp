// Constraint multipliers in the result files: the .dat multiplier blocks (text
// and tools/tethertools/dat.py), and the VTU's CONSTRAINT_FORCE / LAGRANGE_MULTIPLIER
// read back with meshio from a real run of the rigid link example.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "output/tiny_model.hpp"
#include "tether/analysis/static_analysis.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/result_writer.hpp"

namespace tether {
namespace {

using test::fresh_directory;
using test::read_text;
using test::synthetic_results;
using test::tiny_model;

const std::string kSource = TETHER_SOURCE_DIR;

std::string shell_arg(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

std::vector<MultiplierValues> three_constraints() {
  return {
      {"MPC-2 LINK", {0, 4}, {2.0}, {-1.25e-16}, {}},
      {"TIE", {1, 2}, {-5.0, 0.25}, {0.0, 1e-12}, {}},
      {"USER-PENALTY", {3}, {}, {}, {}},  // no multipliers: no block
      {"", {5}, {-0.0}, {3.5}, {}},
  };
}

TEST(MultiplierOutput, DatBlocksInCalculixLayout) {
  const Model model = tiny_model();
  const auto file = fresh_directory("multiplier_dat") / "job.dat";
  {
    DatWriter dat(model, file);
    auto results = synthetic_results(model, 1, 1, 0.5, 0.5);
    results.multipliers = three_constraints();
    dat.write_increment(results, {}, true);
  }
  EXPECT_EQ(read_text(file),
            "\n"
            " constraint multipliers (constraint,equation,f,lambda) for set MPC-2_LINK and time  0.5000000E+00\n"
            "\n"
            "         1    1 -1.250000E-16  2.000000E+00\n"
            "\n"
            " constraint multipliers (constraint,equation,f,lambda) for set TIE and time  0.5000000E+00\n"
            "\n"
            "         2    1  0.000000E+00 -5.000000E+00\n"
            "         2    2  1.000000E-12  2.500000E-01\n"
            "\n"
            " constraint multipliers (constraint,equation,f,lambda) for set C4 and time  0.5000000E+00\n"
            "\n"
            "         4    1  3.500000E+00  0.000000E+00\n");
}

TEST(MultiplierOutput, DatBlocksFollowThePrintRequestsEveryIncrement) {
  const Model model = tiny_model();
  const auto dir = fresh_directory("multiplier_dat_parse");
  OutputRequest u;
  u.kind = OutputRequest::Kind::NodePrint;
  u.set = "LEFT";
  u.variables = {"U"};
  u.frequency = 2;  // U only at increment 2; the multipliers at both
  {
    ResultWriter writer(model, dir, "job");
    for (int inc : {1, 2}) {
      auto results = synthetic_results(model, 1, inc, 0.5 * inc, 0.5 * inc);
      results.multipliers = three_constraints();
      results.multipliers[0].value[0] *= inc;
      writer.write_increment(results, {u}, inc == 2);
    }
  }
  const std::string text = read_text(dir / "job.dat");
  const auto first_u = text.find(" displacements");
  ASSERT_NE(first_u, std::string::npos);
  EXPECT_EQ(text.find(" displacements", first_u + 1), std::string::npos);  // once
  EXPECT_LT(text.find("for set TIE and time  0.5000000E+00"), first_u);       // increment 1 has multipliers
  EXPECT_GT(text.find("for set TIE and time  0.1000000E+01"), first_u);       // after increment 2's U
  if (!std::filesystem::exists("/usr/bin/python3")) GTEST_SKIP() << "/usr/bin/python3 is not installed";
  std::ofstream(dir / "expected.json")
      << R"({"time": 1.0, "blocks": {"MPC-2_LINK": [[1, 1, -1.25e-16, 4.0]],
            "TIE": [[2, 1, 0, -5], [2, 2, 1e-12, 0.25]], "C4": [[4, 1, 3.5, 0]]}})";
  EXPECT_EQ(test::run_python(shell_arg(kSource + "/tests/output/check_multiplier_output.py") + " dat " +
                             shell_arg(dir / "job.dat") + " " + shell_arg(dir / "expected.json")),
            0);
}

TEST(MultiplierOutput, VtuConstraintForceIsSummedPerNode) {
  const Model model = tiny_model();
  auto results = synthetic_results(model, 1, 1, 1.0, 1.0);
  results.multipliers = {{"A", {0, 1}, {2.0}, {0.0}, {{0, {1.0, 2.0}}, {1, {-1.0, -2.0}}}},
                         {"B", {1, 1}, {0.5}, {0.0}, {{1, {0.25, 0.0}}}}};
  std::ostringstream out;
  VtuWriter(model, VtuEncoding::Ascii).write(results, out);
  const std::string text = out.str();
  const auto field = [&](const std::string& name) {
    const auto at = text.find("Name=\"" + name + "\"");
    EXPECT_NE(at, std::string::npos) << name;
    const auto start = text.find('>', at) + 2;
    return text.substr(start, text.find("</DataArray>", start) - start);
  };
  // LAGRANGE_MULTIPLIER: 2 on node 0, 2 + 0.5 on node 1 (B lists node 1 twice: counted once).
  EXPECT_EQ(field("LAGRANGE_MULTIPLIER").substr(0, 8), "2 2.5 0 ");
  EXPECT_EQ(field("CONSTRAINT_FORCE").substr(0, 17), "1 2 0 -0.75 -2 0\n");
}

/// Writes every converged increment through a ResultWriter, as the program does.
class WritingObserver final : public AnalysisObserver {
 public:
  explicit WritingObserver(ResultWriter& writer) : writer_(writer) {}
  void on_results(const IncrementResults& r, const Step& step, bool last) override {
    writer_.write_increment(r, step.outputs, last);
    results.push_back(r);
  }
  std::vector<IncrementResults> results;

 private:
  ResultWriter& writer_;
};

TEST(MultiplierOutput, RigidLinkRunConstraintForceIsMinusTheReaction) {
  const Model model = read_deck(kSource + "/examples/rigid_link/rigid_link.inp");
  const auto dir = fresh_directory("multiplier_rigid_link");
  ResultWriter writer(model, dir, "rigid_link");
  WritingObserver observer(writer);
  const AnalysisSummary summary = StaticAnalysis(model, observer).run();
  ASSERT_TRUE(summary.completed) << summary.message;
  ASSERT_EQ(observer.results.size(), 20u);
  const int a = model.node_index.at(1), b = model.node_index.at(2);
  for (const auto& r : observer.results) {
    const MultiplierValues& m = r.multipliers.at(0);
    ASSERT_EQ(m.nodal_force.size(), 2u);
    EXPECT_EQ(m.nodal_force[0].node, a);
    EXPECT_LT((m.nodal_force[0].force + r.reaction[a]).norm(), 1e-12);
    // At B the link force balances the load P = 3 and the horizontal reaction.
    // Newton's tolerance is 1e-10 q~, but a residual below 1e-8 q~ after a
    // solve is accepted as round-off (q~ is about 3 to 17 here): 1.8e-8 at
    // one increment since the predictor.
    EXPECT_NEAR(m.nodal_force[1].force.y(), 3.0, 1e-7);
    EXPECT_NEAR(m.nodal_force[1].force.x(), -r.reaction[b].x(), 1e-8);
  }
  if (!test::python_with_meshio_available()) GTEST_SKIP() << "/usr/bin/python3 with meshio is not installed";
  EXPECT_EQ(test::run_python(shell_arg(kSource + "/tests/output/check_multiplier_output.py") + " rigid-link " +
                             shell_arg(dir) + " rigid_link 3"),
            0);
}

// Constraints of two or three equations (*TIE slave nodes, *PERIODIC pairs,
// *MPC TIE/PIN/BEAM) put their multipliers at their first node in the vector
// LAGRANGE_MULTIPLIERS; the scalar LAGRANGE_MULTIPLIER is written only when a
// one-equation constraint exists (it was written as zeros for *TIE/*PERIODIC).
TEST(MultiplierOutput, TieAndPeriodicMultipliersAreInTheVtu) {
  for (const std::string deck : {"tie_surface_to_surface", "periodic"}) {
    const Model model = read_deck(kSource + "/tests/smoke/decks/" + deck + ".inp");
    const auto dir = fresh_directory("multiplier_" + deck);
    ResultWriter writer(model, dir, "job", {VtuEncoding::Ascii, true});
    WritingObserver observer(writer);
    const AnalysisSummary summary = StaticAnalysis(model, observer).run();
    ASSERT_TRUE(summary.completed) << summary.message;
    const IncrementResults& last = observer.results.back();
    std::vector<Eigen::Vector3d> expected(model.coords.size(), Eigen::Vector3d::Zero());
    double largest = 0;
    for (const MultiplierValues& m : last.multipliers) {
      ASSERT_EQ(m.value.size(), 2u) << m.owner;
      expected[static_cast<std::size_t>(m.nodes.front())] += Eigen::Vector3d(m.value[0], m.value[1], 0);
      largest = std::max({largest, std::abs(m.value[0]), std::abs(m.value[1])});
    }
    EXPECT_GT(largest, 0) << deck;
    const std::string text = read_text(dir / ("job_1_" + std::to_string(last.increment) + ".vtu"));
    EXPECT_EQ(text.find("Name=\"LAGRANGE_MULTIPLIER\""), std::string::npos) << deck;
    const auto at = text.find("Name=\"LAGRANGE_MULTIPLIERS\"");
    ASSERT_NE(at, std::string::npos) << deck;
    std::istringstream values(text.substr(text.find('>', at) + 1));
    for (const Eigen::Vector3d& e : expected) {
      Eigen::Vector3d v;
      values >> v.x() >> v.y() >> v.z();
      EXPECT_LT((v - e).norm(), 1e-6 * largest) << deck;
    }
  }
}

// An *MPC BEAM's moment on its reference node's rotation is output as
// CONSTRAINT_MOMENT (the reference node 100 carries M = 5: the BEAMs' moment
// there is -5); models without rotations write no such array.
TEST(MultiplierOutput, BeamMomentOnTheReferenceNodeIsInTheVtu) {
  const Model model = read_deck(kSource + "/tests/smoke/decks/mpc_beam.inp");
  const auto dir = fresh_directory("multiplier_beam");
  ResultWriter writer(model, dir, "job", {VtuEncoding::Ascii, true});
  WritingObserver observer(writer);
  const AnalysisSummary summary = StaticAnalysis(model, observer).run();
  ASSERT_TRUE(summary.completed) << summary.message;
  const std::string text = read_text(dir / ("job_1_" + std::to_string(observer.results.back().increment) + ".vtu"));
  const auto at = text.find("Name=\"CONSTRAINT_MOMENT\"");
  ASSERT_NE(at, std::string::npos);
  std::istringstream values(text.substr(text.find('>', at) + 1));
  const int reference = model.node_index.at(100);
  for (int i = 0; i < static_cast<int>(model.coords.size()); ++i) {
    double v = 0;
    values >> v;
    EXPECT_NEAR(v, i == reference ? -5.0 : 0.0, 1e-8) << "node index " << i;
  }
  std::ostringstream tie;
  VtuWriter(tiny_model(), VtuEncoding::Ascii).write(
      [] {
        auto r = synthetic_results(tiny_model(), 1, 1, 1.0, 1.0);
        r.multipliers = three_constraints();
        return r;
      }(),
      tie);
  EXPECT_EQ(tie.str().find("CONSTRAINT_MOMENT"), std::string::npos);
}

}  // namespace
}  // namespace tether
