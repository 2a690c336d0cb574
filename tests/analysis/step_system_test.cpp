// StepSystem: the contributions of a step in assembly order, the prescribed
// and unused dofs, and the symmetry and linearity the contributions declare.

#include "tether/analysis/step_system.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;

namespace {

/// Two CPE4 elements, the upper one resting on the lower (nodes 5-8 on 1-4),
/// base fixed, with `model_data` (surfaces, constraints, contact) before
/// the step and `step_data` inside it.
std::string stacked_pair(const std::string& model_data, const std::string& step_options,
                         const std::string& step_data) {
  return "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n5, 0, 1\n6, 1, 1\n7, 1, 2\n8, 0, 2\n"
         "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1, 2, 3, 4\n2, 5, 6, 7, 8\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
         "*BOUNDARY\n1, 1, 2\n2, 1, 2\n" +
         model_data + "*STEP" + step_options + "\n*STATIC\n" + step_data + "*END STEP\n";
}

const std::string kContact = "*SURFACE, NAME=S\n2, S1\n*SURFACE, NAME=M\n1, S3\n*SURFACE INTERACTION, NAME=I\n";
const std::string kPair = "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nS, M\n";
const std::string kTie = "*EQUATION\n2\n5, 1, 1., 4, 1, -1.\n2\n5, 2, 1., 4, 2, -1.\n2\n6, 1, 1., 3, 1, -1.\n"
                         "2\n6, 2, 1., 3, 2, -1.\n";
const std::string kLoad = "*CLOAD\n7, 2, -1.\n";

struct Built {
  Model model;
  std::unique_ptr<Discretization> discretization;
  std::unique_ptr<StepSystem> system;
  std::vector<std::string> messages;
};

std::unique_ptr<Built> build(const std::string& deck, SolverSettings settings = {}) {
  auto b = std::make_unique<Built>();
  b->model = read_deck_string(deck, "test.inp");
  b->discretization = std::make_unique<Discretization>(b->model);
  const Discretization& disc = *b->discretization;
  const Step& step = b->model.steps.at(0);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(disc.dofs().n_dofs());
  b->system = std::make_unique<StepSystem>(disc, step, make_step_loads(step, disc.dofs(), u, {}, {}), u, 0.0, settings,
                                           [&b](const std::string& m) { b->messages.push_back(m); });
  return b;
}

}  // namespace

TEST(StepSystem, TiedElasticBlocksAreSymmetricAndLinear) {
  const auto b = build(stacked_pair(kTie, "", kLoad));
  EXPECT_TRUE(b->system->symmetric());
  EXPECT_TRUE(b->system->bulk_linear());
  EXPECT_EQ(b->system->n_unused_nodes(), 0);
  EXPECT_TRUE(b->messages.empty());
  // Elements, then the constraints (one per equation); no loads.
  ASSERT_EQ(b->system->contributions().size(), 6u);
  EXPECT_EQ(b->system->contributions()[0], b->discretization->elements()[0].get());
  EXPECT_EQ(b->system->contributions()[2], b->discretization->constraints()[0].get());
  EXPECT_EQ(b->system->contributions()[5], b->discretization->constraints()[3].get());
  EXPECT_TRUE(b->system->load_contributions().empty());
  EXPECT_EQ(b->system->condensed(), nullptr);
}

TEST(StepSystem, NlgeomMakesTheBulkNonlinear) {
  const auto b = build(stacked_pair(kTie, ", NLGEOM", kLoad));
  EXPECT_TRUE(b->system->symmetric());
  EXPECT_FALSE(b->system->bulk_linear());
}

TEST(StepSystem, NonlinearConstraintIsNotLinear) {
  // A rigid link between the blocks: its gradient turns with the link.
  const auto b = build(stacked_pair(kTie + "*MPC\nLINK, 8, 3\n", "", kLoad));
  EXPECT_TRUE(b->system->symmetric());
  EXPECT_FALSE(b->system->bulk_linear());
  EXPECT_FALSE(b->discretization->constraints().back()->linear_in_u(false));
  EXPECT_TRUE(b->discretization->constraints().front()->linear_in_u(false));
}

TEST(StepSystem, FollowerPressureIsUnsymmetricOnlyUnderNlgeom) {
  const std::string pressure = "*DLOAD\n2, P3, 1.\n";
  const auto small = build(stacked_pair(kTie, "", pressure));
  ASSERT_EQ(small->system->pressures().size(), 1u);
  ASSERT_EQ(small->system->load_contributions().size(), 1u);
  EXPECT_EQ(small->system->load_contributions()[0], small->system->pressures()[0].get());
  EXPECT_EQ(small->system->contributions().back(), small->system->pressures()[0].get());
  EXPECT_TRUE(small->system->symmetric());
  EXPECT_TRUE(small->system->bulk_linear());

  const auto large = build(stacked_pair(kTie, ", NLGEOM", pressure));
  EXPECT_FALSE(large->system->symmetric());
  EXPECT_FALSE(large->system->bulk_linear());
}

TEST(StepSystem, FrictionMakesTheTangentUnsymmetricButLeavesTheBulkLinear) {
  const auto frictionless = build(stacked_pair(kContact + kPair, "", kLoad));
  EXPECT_TRUE(frictionless->system->symmetric());
  EXPECT_TRUE(frictionless->system->bulk_linear());  // contact is not part of the bulk
  // Elements, then the pair followed by its slave nodes.
  const auto& c = frictionless->system->contributions();
  const ContactPair* pair = frictionless->discretization->contact_pairs()[0].get();
  ASSERT_EQ(c.size(), 2u + 1u + static_cast<std::size_t>(pair->n_slaves()));
  EXPECT_EQ(c[2], pair);
  EXPECT_EQ(c[3], pair->nodes()[0]);
  EXPECT_FALSE(pair->linear_in_u(false));
  EXPECT_FALSE(pair->nodes()[0]->linear_in_u(false));

  const auto friction = build(stacked_pair(kContact + "*FRICTION\n0.2\n" + kPair, "", kLoad));
  EXPECT_FALSE(friction->system->symmetric());
  EXPECT_TRUE(friction->system->bulk_linear());
  EXPECT_FALSE(friction->discretization->contact_pairs()[0]->nodes()[0]->symmetric_tangent(false));
}

TEST(StepSystem, OneTriangleSolversRefuseAnUnsymmetricTangent) {
  const std::string deck = stacked_pair(kContact + "*FRICTION\n0.2\n" + kPair, "", kLoad);
  for (SolverKind kind : {SolverKind::Mumps, SolverKind::Cholmod}) {
    try {
      build(deck, SolverSettings{kind, true, 0});
      ADD_FAILURE() << "no error";
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find("factorizes symmetric matrices only"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(build(deck, SolverSettings{SolverKind::Umfpack, true, 0}));
  EXPECT_NO_THROW(build(stacked_pair(kTie, "", kLoad), SolverSettings{SolverKind::Mumps, true, 0}));
}

TEST(StepSystem, NodesOfNoElementArePrescribedAndReported) {
  std::string deck = stacked_pair(kTie, "", kLoad);
  deck.replace(deck.find("*ELEMENT"), 8, "9, 5, 5\n*ELEMENT");
  const auto b = build(deck);
  EXPECT_EQ(b->system->n_unused_nodes(), 1);
  ASSERT_EQ(b->messages.size(), 1u);
  EXPECT_EQ(b->messages[0], "1 node(s) belong to no element; they get no degrees of freedom");
  const int node = b->model.node_index.at(9);
  for (int c = 0; c < 2; ++c) EXPECT_TRUE(b->system->equations().is_prescribed(b->discretization->dofs().displacement(node, c)));
  EXPECT_FALSE(b->system->equations().is_prescribed(b->discretization->dofs().displacement(b->model.node_index.at(7), 1)));
}

TEST(StepSystem, RedundantConstraintStopsTheSetUp) {
  // The same tie twice: named before anything is solved.
  EXPECT_THROW(build(stacked_pair(kTie + kTie, "", kLoad)), ModelError);
}
