// Contact output: the *CONTACT PRINT blocks of the .dat (ccx 2.20 layout for
// CSTR/CDIS, tether's CFN/CFS and contact-state blocks), FREQUENCY, and the
// CONTACT_* point data of the .vtu, from an IncrementResults built by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "output/tiny_model.hpp"
#include "tether/core/error.hpp"
#include "tether/output/dat_writer.hpp"
#include "tether/output/result_writer.hpp"
#include "tether/output/vtu_writer.hpp"

namespace tether {
namespace {

using test::fresh_directory;
using test::read_text;
using test::tiny_model;
using Status = ContactNodeValues::Status;

/// tiny_model() with one *CONTACT PAIR (slave TOP, master BASE).
Model contact_model() {
  Model m = tiny_model();
  ContactPairData pair;
  pair.interaction = "SI";
  pair.slave = "TOP";
  pair.master = "BASE";
  m.contact_pairs.push_back(pair);
  return m;
}

ContactNodeValues node_values(const Model& m, int label, Status status, int element, int face, double xi,
                              double gap, double n_force, double pressure, double t_force, double shear, double slip,
                              double total_slip, Eigen::Vector2d force) {
  ContactNodeValues v;
  v.node = m.node_index.at(label);
  v.status = status;
  v.master_element = element;
  v.master_face = face;
  v.xi = xi;
  v.gap = gap;
  v.normal_force = n_force;
  v.pressure = pressure;
  v.tangential_force = t_force;
  v.shear = shear;
  v.slip = slip;
  v.total_slip = total_slip;
  v.force = force;
  return v;
}

/// Master faces of tiny_model() (reference configuration):
///   101 S1: 11 (0,0) -> 12 (1,0)      t = +x, n = (0,-1)
///   103 S3: 21 (1,2) -> 22 (0,2)      t = -x, n = (0, 1)
///   102 S2: 19 (2,0) -> 20 (2,1)      t = +y, n = (1, 0)   (vertical)
///   105 S3: 21 (1,2) -> 20 (2,1)      t = (1,-1)/sqrt2, n = (-1,-1)/sqrt2
/// Forces are consistent: force = N n - T t.
std::vector<ContactPairValues> two_pairs(const Model& m) {
  const double r2 = std::sqrt(2.0);
  ContactPairValues a;
  a.name = "CONTACT PAIR TOP-BASE";
  a.nodes = {
      node_values(m, 22, Status::Slip, 101, 1, -0.25, -1e-9, 3, 150, 0.6, 30, 2e-4, 5e-4, {-0.6, -3}),
      node_values(m, 21, Status::Stick, 103, 3, 0.5, 0, 2, 100, -0.4, -20, -1e-5, 1e-4, {-0.4, 2}),
      node_values(m, 25, Status::Open, 0, 0, 0, 0.3, 0, 0, 0, 0, 0, 0, {0, 0}),
      node_values(m, 20, Status::Slip, 102, 2, 0, -2e-9, 1, 50, 0.2, 10, -3e-4, 3e-4, {1, -0.2}),
      node_values(m, 23, Status::Open, 105, 2, 0.1, 0.05, 0, 0, 0, 0, 0, 0, {0, 0}),
  };
  a.total_force = {0, -1.2};
  ContactPairValues b;
  b.name = "CONTACT PAIR A-B";
  b.nodes = {
      node_values(m, 14, Status::Slip, 105, 3, 0, 0, r2, 1, 0, 0, 0, 0, {-1, -1}),
      node_values(m, 22, Status::Stick, 101, 1, 0, 0, 1, 50, 0.1, 5, 1e-6, 0, {-0.1, -1}),
  };
  b.total_force = {-1.1, -2};
  return {a, b};
}

IncrementResults contact_results(const Model& m, int increment, double time) {
  IncrementResults r;
  r.step = 1;
  r.increment = increment;
  r.step_time = r.total_time = time;
  r.displacement.assign(static_cast<std::size_t>(m.n_nodes()), Eigen::Vector2d::Zero());
  r.contact = two_pairs(m);
  return r;
}

OutputRequest contact_print(std::vector<std::string> variables, int frequency = 1) {
  OutputRequest r;
  r.kind = OutputRequest::Kind::ContactPrint;
  r.variables = std::move(variables);
  r.frequency = frequency;
  r.where = {"job.inp", 7};
  return r;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

const std::string kStateBlocks05 =
    "\n"
    " contact state (slave node,status,gap,pressure,shear,slip,total slip,master elem,master face,xi) for pair "
    "TOP-BASE and time  0.5000000E+00\n"
    "\n"
    "        22    2 -1.000000E-09  1.500000E+02  3.000000E+01  2.000000E-04  5.000000E-04       101    1 -2.500000E-01\n"
    "        21    1  0.000000E+00  1.000000E+02 -2.000000E+01 -1.000000E-05  1.000000E-04       103    3  5.000000E-01\n"
    "        25    0  3.000000E-01  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00         0    0  0.000000E+00\n"
    "        20    2 -2.000000E-09  5.000000E+01  1.000000E+01 -3.000000E-04  3.000000E-04       102    2  0.000000E+00\n"
    "        23    0  5.000000E-02  0.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00       105    2  1.000000E-01\n"
    "\n"
    " contact state (slave node,status,gap,pressure,shear,slip,total slip,master elem,master face,xi) for pair "
    "CONTACT_PAIR_A-B and time  0.5000000E+00\n"
    "\n"
    "        14    2  0.000000E+00  1.000000E+00  0.000000E+00  0.000000E+00  0.000000E+00       105    3  0.000000E+00\n"
    "        22    1  0.000000E+00  5.000000E+01  5.000000E+00  1.000000E-06  0.000000E+00       101    1  0.000000E+00\n";

TEST(ContactOutput, DatBlocksInCalculixLayout) {
  const Model model = contact_model();
  const auto file = fresh_directory("contact_dat") / "job.dat";
  {
    DatWriter dat(model, file);
    dat.write_increment(contact_results(model, 1, 0.5), {contact_print({"CSTR", "CDIS", "CFN", "CFS"})}, false);
  }
  // tang1 along ccx's in-plane tangent (positive x component): +shear on 101 S1
  // (t = +x), -shear on 103 S3 (t = -x); on the vertical face 102 S2 the shear
  // goes to tang2 = n x e3 = -t. Only closed nodes (stick, slip) are printed.
  const std::string expected =
      "\n"
      " contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.5000000E+00\n"
      "\n"
      "        22  1.500000E+02  3.000000E+01  0.000000E+00\n"
      "        21  1.000000E+02  2.000000E+01  0.000000E+00\n"
      "        20  5.000000E+01  0.000000E+00 -1.000000E+01\n"
      "        14  1.000000E+00  0.000000E+00  0.000000E+00\n"
      "        22  5.000000E+01  5.000000E+00  0.000000E+00\n"
      "\n"
      " relative contact displacement (slave node,normal,tang1,tang2) for all contact elements and time 0.5000000E+00\n"
      "\n"
      "        22 -1.000000E-09  2.000000E-04  0.000000E+00\n"
      "        21  0.000000E+00  1.000000E-05  0.000000E+00\n"
      "        20 -2.000000E-09  0.000000E+00  3.000000E-04\n"
      "        14  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "        22  0.000000E+00  1.000000E-06  0.000000E+00\n"
      "\n"
      " total normal contact force (fx,fy,fz) for pair TOP-BASE and time  0.5000000E+00\n"
      "\n"
      "        1.000000E+00 -1.000000E+00  0.000000E+00\n"
      "\n"
      " total normal contact force (fx,fy,fz) for pair CONTACT_PAIR_A-B and time  0.5000000E+00\n"
      "\n"
      "       -1.000000E+00 -2.000000E+00  0.000000E+00\n"
      "\n"
      " total shear contact force (fx,fy,fz) for pair TOP-BASE and time  0.5000000E+00\n"
      "\n"
      "       -1.000000E+00 -2.000000E-01  0.000000E+00\n"
      "\n"
      " total shear contact force (fx,fy,fz) for pair CONTACT_PAIR_A-B and time  0.5000000E+00\n"
      "\n"
      "       -1.000000E-01  0.000000E+00  0.000000E+00\n" +
      kStateBlocks05;
  EXPECT_EQ(read_text(file), expected);
}

TEST(ContactOutput, NormalAndShearForcesAddUpToTheTotalForce) {
  const Model model = contact_model();
  const auto results = contact_results(model, 1, 1.0);
  for (const auto& pair : results.contact) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const auto& v : pair.nodes) sum += v.force;
    EXPECT_NEAR((sum - pair.total_force).norm(), 0, 1e-14) << pair.name;  // the fixture is consistent
  }
  const auto file = fresh_directory("contact_forces") / "job.dat";
  {
    DatWriter dat(model, file);
    dat.write_increment(results, {contact_print({"CFN", "CFS"})}, true);
  }
  const std::string text = read_text(file);
  // TOP-BASE: CFN (1, -1) + CFS (-1, -0.2) = total force (0, -1.2).
  EXPECT_NE(text.find("for pair TOP-BASE and time  0.1000000E+01\n\n        1.000000E+00 -1.000000E+00"),
            std::string::npos);
  EXPECT_NE(text.find("for pair TOP-BASE and time  0.1000000E+01\n\n       -1.000000E+00 -2.000000E-01"),
            std::string::npos);
}

TEST(ContactOutput, CdisSumsTheSlipOfTheClosedIncrements) {
  const Model model = contact_model();
  const auto file = fresh_directory("contact_cdis_sum") / "job.dat";
  {
    DatWriter dat(model, file);
    auto r = contact_results(model, 1, 0.25);
    dat.write_increment(r, {contact_print({"CDIS"})}, false);
    r = contact_results(model, 2, 0.5);
    r.contact[0].nodes[0].status = Status::Open;  // open: its slip does not count
    r.contact[0].nodes[0].slip = 1.0;
    dat.write_increment(r, {contact_print({"CDIS"}, 0)}, false);  // not printed, still summed
    r = contact_results(model, 3, 1.0);
    r.contact[0].nodes[0].slip = 1e-4;
    dat.write_increment(r, {contact_print({"CDIS"})}, true);
  }
  const std::string text = read_text(file);
  EXPECT_EQ(count(text, "relative contact displacement"), 2);
  const auto at = text.find("and time 0.1000000E+01");
  ASSERT_NE(at, std::string::npos);
  const std::string last = text.substr(at);
  EXPECT_NE(last.find("        22 -1.000000E-09  3.000000E-04  0.000000E+00\n"), std::string::npos) << last;  // 2e-4 + 1e-4
  EXPECT_NE(last.find("        21  0.000000E+00  3.000000E-05  0.000000E+00\n"), std::string::npos) << last;  // 3 x 1e-5
  EXPECT_NE(last.find("        20 -2.000000E-09  0.000000E+00  9.000000E-04\n"), std::string::npos) << last;
}

TEST(ContactOutput, TangentDirectionIsTheCurrentFaces) {
  const Model model = contact_model();
  const auto file = fresh_directory("contact_current_face") / "job.dat";
  auto r = contact_results(model, 1, 1.0);
  // Node 12 moved to x = -1: face 101 S1 now runs 11 -> 12 towards -x, so the
  // ccx tangent (+x) is -t and tang1 = -shear.
  r.displacement[static_cast<std::size_t>(model.node_index.at(12))] = {-2, 0};
  {
    DatWriter dat(model, file);
    dat.write_increment(r, {contact_print({"CSTR"})}, true);
  }
  const std::string text = read_text(file);
  EXPECT_NE(text.find("        22  1.500000E+02 -3.000000E+01  0.000000E+00\n"), std::string::npos) << text;
  EXPECT_NE(text.find("        22  5.000000E+01 -5.000000E+00  0.000000E+00\n"), std::string::npos) << text;
  EXPECT_NE(text.find("        21  1.000000E+02  2.000000E+01  0.000000E+00\n"), std::string::npos) << text;
}

TEST(ContactOutput, HonoursFrequencyAndWritesTheStateWhenAContactPrintIsDue) {
  const Model model = contact_model();
  const auto file = fresh_directory("contact_frequency") / "job.dat";
  {
    DatWriter dat(model, file);
    for (int inc = 1; inc <= 5; ++inc)
      dat.write_increment(contact_results(model, inc, 0.2 * inc),
                          {contact_print({"CSTRESS"}, 2), contact_print({"CDISP"}, 0)}, inc == 5);
  }
  const std::string text = read_text(file);
  EXPECT_EQ(count(text, "contact stress"), 3);  // increments 2, 4 and the last
  EXPECT_EQ(count(text, "relative contact displacement"), 0);
  EXPECT_EQ(count(text, "contact state"), 6);  // two pairs at each of those increments
  EXPECT_EQ(count(text, "for all contact elements and time 0.4000000E+00"), 1);
  EXPECT_EQ(count(text, "for all contact elements and time 0.8000000E+00"), 1);
  EXPECT_EQ(count(text, "for all contact elements and time 0.1000000E+01"), 1);
  EXPECT_EQ(count(text, "and time 0.2000000E+00"), 0);
  EXPECT_EQ(count(text, "for pair TOP-BASE and time  0.1000000E+01"), 1);

  // Without a *CONTACT PRINT there are no contact blocks at all.
  const auto quiet = fresh_directory("contact_no_print") / "job.dat";
  {
    DatWriter dat(model, quiet);
    dat.write_increment(contact_results(model, 1, 1.0), {}, true);
  }
  EXPECT_EQ(read_text(quiet), "");
}

TEST(ContactOutput, CelsIsAcceptedAndUnknownVariablesAreRefused) {
  const Model model = contact_model();
  const auto file = fresh_directory("contact_variables") / "job.dat";
  DatWriter dat(model, file);
  const auto r = contact_results(model, 1, 0.5);
  try {
    dat.write_increment(r, {contact_print({"CSTR"}), contact_print({"CNUM"})}, true);
    FAIL() << "CNUM accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("job.inp:7"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("CNUM"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text(file), "");
  EXPECT_NO_THROW(DatWriter::check(model, contact_print({"CSTR", "CDIS", "CSTRESS", "CDISP", "CFN", "CFS", "CELS"})));
  dat.write_increment(r, {contact_print({"CELS"})}, true);  // no energy block, the state blocks only
  EXPECT_EQ(read_text(file), kStateBlocks05);
}

TEST(ContactOutput, ModelWithoutContactPairsPrintsEmptyBlocks) {
  const Model model = tiny_model();
  const auto file = fresh_directory("contact_none") / "job.dat";
  {
    DatWriter dat(model, file);
    auto r = contact_results(model, 1, 1.0);
    r.contact.clear();
    dat.write_increment(r, {contact_print({"CSTR", "CFN"})}, true);
  }
  EXPECT_EQ(read_text(file),
            "\n"
            " contact stress (slave node,press,tang1,tang2) for all contact elements and time 0.1000000E+01\n"
            "\n");
}

TEST(ContactOutput, PairNames) {
  const Model model = contact_model();
  auto contact = two_pairs(model);
  EXPECT_EQ(contact_pair_set_name(model, contact, 0), "TOP-BASE");
  EXPECT_EQ(contact_pair_set_name(model, contact, 1), "CONTACT_PAIR_A-B");
  contact[1].name.clear();
  EXPECT_EQ(contact_pair_set_name(model, contact, 1), "P2");
}

TEST(ContactOutput, RefusesBadNodesAndUnknownMasterFaces) {
  const Model model = contact_model();
  DatWriter dat(model, fresh_directory("contact_bad") / "job.dat");
  auto r = contact_results(model, 1, 1.0);
  r.contact[0].nodes[1].node = 99;
  EXPECT_THROW(dat.write_increment(r, {contact_print({"CSTR"})}, true), std::invalid_argument);
  r = contact_results(model, 1, 1.0);
  r.contact[0].nodes[0].master_element = 999;  // carries a force: CFN needs its face
  EXPECT_THROW(dat.write_increment(r, {contact_print({"CFN"})}, true), std::invalid_argument);
  EXPECT_NO_THROW(dat.write_increment(r, {contact_print({"CSTR"})}, true));  // CSTR does not
  r.contact[0].nodes[1].node = 99;
  std::ostringstream vtu;
  EXPECT_THROW(VtuWriter(model, VtuEncoding::Ascii).write(r, vtu), std::invalid_argument);
}

/// Values of the ASCII DataArray `name` inside <PointData>.
std::vector<double> point_array(const std::string& vtu, const std::string& name) {
  const auto point_data = vtu.find("<PointData");
  const auto at = vtu.find("Name=\"" + name + "\"", point_data);
  if (at == std::string::npos || at > vtu.find("</PointData>")) return {};
  const auto begin = vtu.find('>', at) + 1;
  const auto end = vtu.find("</DataArray>", begin);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<double> values;
  for (std::string token; in >> token;) values.push_back(std::strtod(token.c_str(), nullptr));
  return values;
}

/// CONTACT_* point data expected for contact_results() on the slave nodes;
/// node 22 is slave in both pairs: sums, smallest gap, highest status.
struct ExpectedPoint {
  int label;
  double slave, status, pressure, gap, shear, slip, fx, fy;
};
const std::vector<ExpectedPoint> kExpectedSlaves = {
    {22, 1, 2, 200, -1e-9, 35, 5e-4, -0.7, -4}, {21, 1, 1, 100, 0, -20, 1e-4, -0.4, 2},
    {25, 1, 0, 0, 0.3, 0, 0, 0, 0},            {20, 1, 2, 50, -2e-9, 10, 3e-4, 1, -0.2},
    {23, 1, 0, 0, 0.05, 0, 0, 0, 0},           {14, 1, 2, 1, 0, 0, 0, -1, -1},
};

/// Every node: the slave nodes as above, the others 0 with status -1.
std::vector<ExpectedPoint> expected_points(const Model& m) {
  std::vector<ExpectedPoint> all;
  for (const int label : m.node_ids) all.push_back({label, 0, -1, 0, 0, 0, 0, 0, 0});
  for (const auto& e : kExpectedSlaves) all[static_cast<std::size_t>(m.node_index.at(e.label))] = e;
  return all;
}

TEST(ContactOutput, VtuPointDataOnAllNodes) {
  const Model model = contact_model();
  std::ostringstream out;
  VtuWriter(model, VtuEncoding::Ascii).write(contact_results(model, 1, 1.0), out);
  const std::string text = out.str();
  EXPECT_NE(text.find("<DataArray type=\"Int64\" Name=\"CONTACT_SLAVE\" format=\"ascii\">"), std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"Int64\" Name=\"CONTACT_STATUS\" format=\"ascii\">"), std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"Float64\" Name=\"CONTACT_FORCE\" NumberOfComponents=\"3\" format=\"ascii\">"),
            std::string::npos);
  const auto n = static_cast<std::size_t>(model.n_nodes());
  const auto slave = point_array(text, "CONTACT_SLAVE"), status = point_array(text, "CONTACT_STATUS"),
             pressure = point_array(text, "CONTACT_PRESSURE"), gap = point_array(text, "CONTACT_GAP"),
             shear = point_array(text, "CONTACT_SHEAR"), slip = point_array(text, "CONTACT_SLIP"),
             force = point_array(text, "CONTACT_FORCE");
  ASSERT_EQ(slave.size(), n);
  ASSERT_EQ(status.size(), n);
  ASSERT_EQ(pressure.size(), n);
  ASSERT_EQ(gap.size(), n);
  ASSERT_EQ(shear.size(), n);
  ASSERT_EQ(slip.size(), n);
  ASSERT_EQ(force.size(), 3 * n);
  const auto expected = expected_points(model);
  for (std::size_t i = 0; i < n; ++i) {
    const ExpectedPoint& e = expected[i];
    EXPECT_EQ(slave[i], e.slave) << e.label;
    EXPECT_EQ(status[i], e.status) << e.label;
    EXPECT_NEAR(pressure[i], e.pressure, 1e-12) << e.label;
    EXPECT_NEAR(gap[i], e.gap, 1e-20) << e.label;
    EXPECT_NEAR(shear[i], e.shear, 1e-12) << e.label;
    EXPECT_NEAR(slip[i], e.slip, 1e-18) << e.label;
    EXPECT_NEAR(force[3 * i], e.fx, 1e-12) << e.label;
    EXPECT_NEAR(force[3 * i + 1], e.fy, 1e-12) << e.label;
    EXPECT_EQ(force[3 * i + 2], 0) << e.label;
  }
}

TEST(ContactOutput, VtuHasNoContactArraysWithoutContactPairs) {
  const Model model = tiny_model();
  auto r = contact_results(model, 1, 1.0);
  r.contact.clear();
  std::ostringstream out;
  VtuWriter(model).write(r, out);
  EXPECT_EQ(out.str().find("CONTACT_"), std::string::npos);
}

TEST(ContactOutput, ContactFileRequestsScheduleTheVtuLikeNodeFile) {
  const Model model = contact_model();
  const auto dir = fresh_directory("contact_file");
  OutputRequest file;
  file.kind = OutputRequest::Kind::ContactFile;
  file.variables = {"CSTR"};
  file.frequency = 2;
  {
    ResultWriter writer(model, dir, "job");
    for (int inc = 1; inc <= 3; ++inc) writer.write_increment(contact_results(model, inc, inc / 3.0), {file}, inc == 3);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "job_1_1.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "job_1_2.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir / "job_1_3.vtu"));  // the last increment of the step
  EXPECT_NE(read_text(dir / "job_1_3.vtu").find("Name=\"CONTACT_PRESSURE\""), std::string::npos);
  EXPECT_EQ(read_text(dir / "job.dat"), "");  // *CONTACT FILE prints nothing
}


// ------------------------------------------------------------ Python readers

const std::string kScripts = std::string(TETHER_SOURCE_DIR) + "/tests/output/";

std::string shell_arg(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

bool python_available() { return std::filesystem::exists("/usr/bin/python3"); }

TEST(ContactOutput, PythonReadersReadCalculixContactBlocks) {
  if (!python_available()) GTEST_SKIP() << "/usr/bin/python3 is not installed";
  // A real ccx 2.20 run (data/ccx220_contact_nts.inp): CSTR, CDIS and CELS
  // ("forall contact elements") blocks, read by tools/tethertools/dat.py.
  EXPECT_EQ(test::run_python(shell_arg(kScripts + "check_datfile.py") + " " +
                             shell_arg(kScripts + "data/ccx220_contact_nts.dat") + " " +
                             shell_arg(kScripts + "data/ccx220_contact_nts.json")),
            0);
}

TEST(ContactOutput, PythonReadersReadTetherContactBlocks) {
  if (!python_available()) GTEST_SKIP() << "/usr/bin/python3 is not installed";
  const Model model = contact_model();
  const auto dir = fresh_directory("contact_python_dat");
  {
    DatWriter dat(model, dir / "job.dat");
    for (int inc : {1, 2})
      dat.write_increment(contact_results(model, inc, 0.5 * inc), {contact_print({"CSTR", "CDIS", "CFN", "CFS"})},
                          inc == 2);
  }
  std::string json = "[";
  for (int inc : {1, 2}) {
    const std::string time = inc == 1 ? "0.5" : "1.0";
    const auto block = [&](const std::string& title, const std::string& set, const std::string& rows) {
      json += R"({"title": ")" + title + R"(", "set": ")" + set + R"(", "time": )" + time + ", " + rows + "},";
    };
    block("contact stress (slave node,press,tang1,tang2)", "",
          R"("rows": [[22, 150, 30, 0], [21, 100, 20, 0], [20, 50, 0, -10], [14, 1, 0, 0], [22, 50, 5, 0]])");
    const auto sum = [inc](double slip) {  // CDIS sums the slip: inc times the increment's
      std::ostringstream o;
      o.precision(17);
      o << slip * inc;
      return o.str();
    };
    block("relative contact displacement (slave node,normal,tang1,tang2)", "",
          "\"rows\": [[22, -1e-9, " + sum(2e-4) + ", 0], [21, 0, " + sum(1e-5) + ", 0], [20, -2e-9, 0, " + sum(3e-4) +
              "], [14, 0, 0, 0], [22, 0, " + sum(1e-6) + ", 0]]");
    block("total normal contact force (fx,fy,fz)", "TOP-BASE", R"("rows": [[1, -1, 0]])");
    block("total normal contact force (fx,fy,fz)", "CONTACT_PAIR_A-B", R"("rows": [[-1, -2, 0]])");
    block("total shear contact force (fx,fy,fz)", "TOP-BASE", R"("rows": [[-1, -0.2, 0]])");
    block("total shear contact force (fx,fy,fz)", "CONTACT_PAIR_A-B", R"("rows": [[-0.1, 0, 0]])");
    const std::string state(kContactStateTitle);
    block(state, "TOP-BASE", R"("n_rows": 5, "first_row": [22, 2, -1e-9, 150, 30, 2e-4, 5e-4, 101, 1, -0.25])");
    block(state, "CONTACT_PAIR_A-B", R"("n_rows": 2, "first_row": [14, 2, 0, 1, 0, 0, 0, 105, 3, 0])");
  }
  json.back() = ']';
  std::ofstream(dir / "expected.json") << json;
  EXPECT_EQ(test::run_python(shell_arg(kScripts + "check_datfile.py") + " " + shell_arg(dir / "job.dat") + " " +
                             shell_arg(dir / "expected.json")),
            0);
}

TEST(ContactOutput, MeshioReadsTheContactArrays) {
  if (!test::python_with_meshio_available()) GTEST_SKIP() << "/usr/bin/python3 with meshio is not installed";
  const Model model = contact_model();
  const auto dir = fresh_directory("contact_meshio");
  {
    ResultWriter writer(model, dir, "job");  // base64 (binary) arrays
    writer.write_increment(contact_results(model, 1, 1.0), {}, false);
    auto r = contact_results(model, 2, 2.0);
    r.contact.clear();
    writer.write_increment(r, {}, true);
  }
  const auto expected = expected_points(model);
  std::ostringstream j;
  j.precision(17);
  const auto list = [&](const char* name, auto value) {
    j << '"' << name << "\": [";
    for (std::size_t i = 0; i < expected.size(); ++i) j << (i ? ", " : "") << value(expected[i]);
    j << "], ";
  };
  j << '{';
  list("CONTACT_SLAVE", [](const ExpectedPoint& e) { return e.slave; });
  list("CONTACT_STATUS", [](const ExpectedPoint& e) { return e.status; });
  list("CONTACT_PRESSURE", [](const ExpectedPoint& e) { return e.pressure; });
  list("CONTACT_GAP", [](const ExpectedPoint& e) { return e.gap; });
  list("CONTACT_SHEAR", [](const ExpectedPoint& e) { return e.shear; });
  list("CONTACT_SLIP", [](const ExpectedPoint& e) { return e.slip; });
  j << "\"CONTACT_FORCE\": [";
  for (std::size_t i = 0; i < expected.size(); ++i)
    j << (i ? ", " : "") << '[' << expected[i].fx << ", " << expected[i].fy << ", 0]";
  j << "]}";
  std::ofstream(dir / "contact.json") << j.str();
  std::ofstream(dir / "none.json") << R"({"CONTACT_SLAVE": null, "CONTACT_FORCE": null})";
  EXPECT_EQ(test::run_python(shell_arg(kScripts + "check_point_data.py") + " " + shell_arg(dir / "job_1_1.vtu") + " " +
                             shell_arg(dir / "contact.json")),
            0);
  EXPECT_EQ(test::run_python(shell_arg(kScripts + "check_point_data.py") + " " + shell_arg(dir / "job_1_2.vtu") + " " +
                             shell_arg(dir / "none.json")),
            0);
}

}  // namespace
}  // namespace tether
