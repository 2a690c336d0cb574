// *DYNAMIC, EXPLICIT with predictor-corrector contact and constraints: the
// bar on a rigid wall, momentum conservation, colliding rings, the cylinder
// in a ring, Coulomb friction, a tied bar.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "bar_decks.hpp"
#include "run_deck.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/stable_increment.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/restart_file.hpp"
#include "explicit_decks.hpp"

namespace tether {
namespace {

using DeckRun = tether::testing::Run;
using tether::testing::run_deck_text;
using namespace tether::testing;  // explicit_decks.hpp, bar_decks.hpp

TEST(ExplicitContact, ElasticBarHitsARigidWall) {
  // Contact lasts 2 L / c_p at the force rho c_p v0 A; the bar leaves at +v0.
  const int n = 100;
  const double h = 0.01, v0 = 1, length = n * h, duration = 2 * length / kCp;
  const DeckRun run = run_deck_text(wall_deck(n, h, v0, 1.1 * duration));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double expected = kRho * kCp * v0 * h;
  double force_sum = 0, previous_force = 0, previous_time = 0, released = -1, worst_penetration = 0;
  int n_force = 0;
  for (const IncrementResults& r : run.recorder.results) {
    double force = 0;
    for (int node : run.model.node_sets.at("WALLN")) force += r.reaction[static_cast<std::size_t>(node)].x();
    ASSERT_EQ(r.contact.size(), 1u);
    EXPECT_NEAR(r.contact[0].total_force.x(), force, 1e-9 * expected);  // the pair's force is the wall's
    if (r.step_time > 0.05 * duration && r.step_time < 0.95 * duration) force_sum += force, ++n_force;
    // Release: the force falls through half its value (linear between reports).
    if (released < 0 && previous_force > 0.5 * expected && force <= 0.5 * expected)
      released = previous_time + (r.step_time - previous_time) * (previous_force - 0.5 * expected) / (previous_force - force);
    previous_force = force, previous_time = r.step_time;
    for (int node : run.model.node_sets.at("LEFT"))
      worst_penetration = std::max(worst_penetration, -r.displacement[static_cast<std::size_t>(node)].x());
  }
  double mean_velocity = 0;
  for (int node : run.model.node_sets.at("ALLN")) mean_velocity += run.last().velocity[static_cast<std::size_t>(node)].x();
  mean_velocity /= static_cast<double>(run.model.node_sets.at("ALLN").size());
  const double force = force_sum / n_force;
  std::printf("contact force %.6g against %.6g (%.3g %%), duration %.6g against %.6g (%.3g %%), rebound %.6g "
              "(%.3g %%), penetration %.3g, numerical energy %.3g of %.6g\n",
              force, expected, 100 * (force / expected - 1), released, duration, 100 * (released / duration - 1),
              mean_velocity, 100 * (mean_velocity / v0 - 1), worst_penetration, run.last().energy->numerical,
              run.recorder.results.front().energy->total);
  EXPECT_NEAR(force / expected, 1, 0.02);
  EXPECT_NEAR(released / duration, 1, 0.02);
  EXPECT_NEAR(mean_velocity / v0, 1, 0.02);
  EXPECT_LT(worst_penetration, 1e-12 * h);  // a rigid master: the correction is exact
}

TEST(ExplicitContact, CorrectorConservesLinearMomentum) {
  // Two free unit-density squares: A (0.8 x 0.8) moving at (2, 0.5) onto B
  // (1 x 1) at rest, A's right face the slave, B's left face the master;
  // they touch at t = 0, slide along the face (without friction, or stick
  // and slip with mu = 0.5) and part.
  for (const std::string friction : {"", "*FRICTION\n0.5\n"}) {
    SCOPED_TRACE(friction.empty() ? "frictionless" : "mu = 0.5");
    const std::string deck =
        "*NODE\n1, -0.8, 0.1\n2, 0, 0.1\n3, 0, 0.9\n4, -0.8, 0.9\n5, 0, 0\n6, 1, 0\n7, 1, 1\n8, 0, 1\n"
        "*ELEMENT, TYPE=CPE4, ELSET=A\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=CPE4, ELSET=B\n2, 5, 6, 7, 8\n"
        "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n1.\n*SOLID SECTION, ELSET=A, MATERIAL=M\n"
        "*SOLID SECTION, ELSET=B, MATERIAL=M\n*SURFACE, NAME=AR\n1, S2\n*SURFACE, NAME=BL\n2, S4\n"
        "*SURFACE INTERACTION, NAME=I\n" +
        friction +
        "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nAR, BL\n"
        "*NSET, NSET=AN\n1, 2, 3, 4\n*INITIAL CONDITIONS, TYPE=VELOCITY\nAN, 1, 2.\nAN, 2, 0.5\n"
        "*STEP\n*DYNAMIC, EXPLICIT\n, 0.2\n*END STEP\n";
    const DeckRun run = run_deck_text(deck);
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const double mass_a = 0.64 / 4, mass_b = 0.25;  // lumped, per node
    const Eigen::Vector2d initial(4 * mass_a * 2, 4 * mass_a * 0.5);
    bool touched = false;
    for (const IncrementResults& r : run.recorder.results) {
      Eigen::Vector2d momentum(0, 0);
      for (int i = 0; i < 8; ++i) momentum += (i < 4 ? mass_a : mass_b) * r.velocity[static_cast<std::size_t>(i)];
      EXPECT_NEAR((momentum - initial).norm(), 0, 1e-13 * initial.norm()) << "time " << r.step_time;
      touched = touched || r.contact[0].total_force.norm() > 0;
      EXPECT_GE(r.energy->numerical, -1e-12);  // the kinematic corrector never adds energy here
    }
    EXPECT_TRUE(touched);
    // Without friction B is pushed along x only (vertical face): its y momentum stays 0; friction drags it up.
    double b_momentum_y = 0, b_momentum_x = 0;
    for (int i = 4; i < 8; ++i) {
      b_momentum_x += mass_b * run.last().velocity[static_cast<std::size_t>(i)].x();
      b_momentum_y += mass_b * run.last().velocity[static_cast<std::size_t>(i)].y();
    }
    EXPECT_GT(b_momentum_x, 0.1 * initial.x());
    if (friction.empty())
      EXPECT_NEAR(b_momentum_y, 0, 0.02 * initial.norm());
    else
      EXPECT_GT(b_momentum_y, 0.02 * initial.norm());
  }
}

/// Nodes and CPE4 of an n x n block of side `size` with its lower left corner
/// at (x0, y0), labels from `first_node` / `first_element`, in ELSET `elset`;
/// node (i, j) is first_node + j (n + 1) + i. Element (i, j) is
/// first_element + j n + i; its face S2 is on x = x0 + size when i = n - 1, S4 on x = x0 when i = 0.
std::string block_mesh(int first_node, int first_element, double x0, double y0, double size, int n,
                       const std::string& elset) {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE, NSET=" << elset << "N\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) d << first_node + j * (n + 1) + i << ", " << x0 + size * i / n << ", " << y0 + size * j / n << "\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=" << elset << "\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = first_node + j * (n + 1) + i;
      d << first_element + j * n + i << ", " << a << ", " << a + 1 << ", " << a + n + 2 << ", " << a + n + 1 << "\n";
    }
  return d.str();
}

/// Linear and angular momentum (about the origin, of the positions X + u) of a report [N s], [N m s].
struct Momentum {
  Eigen::Vector2d linear{0, 0};
  double angular = 0;
};
Momentum momentum(const IncrementResults& r, const Model& model, const Eigen::VectorXd& nodal_mass) {
  Momentum m;
  for (std::size_t i = 0; i < model.coords.size(); ++i) {
    const Eigen::Vector2d x = model.coords[i] + r.displacement[i];
    const Eigen::Vector2d v = r.velocity[i];
    m.linear += nodal_mass[static_cast<Eigen::Index>(i)] * v;
    m.angular += nodal_mass[static_cast<Eigen::Index>(i)] * (x.x() * v.y() - x.y() * v.x());
  }
  return m;
}

/// The lumped mass of each node of a deck's first step [mass].
Eigen::VectorXd nodal_masses(const std::string& deck);

TEST(ExplicitContact, CorrectorConservesAngularMomentum) {
  // A 3 x 3 block moving at (2, 0.5) hits the upper half of a resting 4 x 4
  // block off its centre (NLGEOM: the elements' forces are objective). The
  // corrector's forces act along the gap gradient at t_n, whose moment about
  // the positions of t_n is zero: the angular momentum is that of the start to round-off.
  const std::string deck = block_mesh(1, 1, -0.8, 0.5, 0.8, 3, "A") + block_mesh(101, 101, 0, 0, 1, 4, "B") +
                           "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n1.\n*SOLID SECTION, ELSET=A, MATERIAL=M\n"
                           "*SOLID SECTION, ELSET=B, MATERIAL=M\n*SURFACE, NAME=AR\n3, S2\n6, S2\n9, S2\n"
                           "*SURFACE, NAME=BL\n101, S4\n105, S4\n109, S4\n113, S4\n*SURFACE INTERACTION, NAME=I\n"
                           "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nAR, BL\n"
                           "*INITIAL CONDITIONS, TYPE=VELOCITY\nAN, 1, 2.\nAN, 2, 0.5\n"
                           "*STEP, NLGEOM\n*DYNAMIC, EXPLICIT\n, 0.3\n*END STEP\n";
  const DeckRun run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const Eigen::VectorXd mass = nodal_masses(deck);
  Momentum start;
  for (std::size_t i = 0; i < run.model.coords.size(); ++i) {
    const Eigen::Vector2d v = i < 16 ? Eigen::Vector2d(2, 0.5) : Eigen::Vector2d(0, 0);
    start.linear += mass[static_cast<Eigen::Index>(i)] * v;
    start.angular += mass[static_cast<Eigen::Index>(i)] * (run.model.coords[i].x() * v.y() - run.model.coords[i].y() * v.x());
  }
  double worst_linear = 0, worst_angular = 0, b_spin = 0;
  int touching = 0;
  for (const IncrementResults& r : run.recorder.results) {
    const Momentum m = momentum(r, run.model, mass);
    worst_linear = std::max(worst_linear, (m.linear - start.linear).norm());
    worst_angular = std::max(worst_angular, std::abs(m.angular - start.angular));
    touching += r.contact[0].total_force.norm() > 0;
  }
  // B's spin about its centre of mass at the end: the impact was off centre.
  const IncrementResults& end = run.last();
  Eigen::Vector2d centre(0, 0), b_velocity(0, 0);
  double b_mass = 0;
  for (std::size_t i = 16; i < run.model.coords.size(); ++i) {
    const double m = mass[static_cast<Eigen::Index>(i)];
    centre += m * (run.model.coords[i] + end.displacement[i]), b_velocity += m * end.velocity[i], b_mass += m;
  }
  centre /= b_mass, b_velocity /= b_mass;
  for (std::size_t i = 16; i < run.model.coords.size(); ++i) {
    const Eigen::Vector2d x = run.model.coords[i] + end.displacement[i] - centre, v = end.velocity[i] - b_velocity;
    b_spin += mass[static_cast<Eigen::Index>(i)] * (x.x() * v.y() - x.y() * v.x());
  }
  std::printf("reports in contact %d; worst momentum change: linear %.3g of %.3g, angular %.3g of %.3g; B's spin %.3g\n",
              touching, worst_linear, start.linear.norm(), worst_angular, std::abs(start.angular), b_spin);
  EXPECT_GT(touching, 5);
  EXPECT_GT(std::abs(b_spin), 0.01 * std::abs(start.angular));  // the test sees rotation
  EXPECT_LT(worst_linear, 1e-13 * start.linear.norm());
  EXPECT_LT(worst_angular, 1e-13 * std::abs(start.angular));
}

/// The momentum of the initial velocities of `model` (masses `mass` per node).
Momentum initial_momentum(const Model& model, const Eigen::VectorXd& mass) {
  std::vector<Eigen::Vector2d> v(model.coords.size(), Eigen::Vector2d::Zero());
  for (const auto& iv : model.initial_velocities) v[static_cast<std::size_t>(iv.node)][iv.dof] = iv.value;
  Momentum m;
  for (std::size_t i = 0; i < v.size(); ++i) {
    m.linear += mass[static_cast<Eigen::Index>(i)] * v[i];
    m.angular += mass[static_cast<Eigen::Index>(i)] * (model.coords[i].x() * v[i].y() - model.coords[i].y() * v[i].x());
  }
  return m;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ExplicitContact, WithFrictionAngularMomentumChangesOnlyWhereSlavesArrive) {
  // The off-centre impact with mu = 0.3: a friction force has the moment
  // g_n lambda_t about x_n, zero once the slave sits on the master. Linear
  // momentum stays exact; angular momentum changes a little, at arrivals.
  const std::string deck = block_mesh(1, 1, -0.8, 0.5, 0.8, 3, "A") + block_mesh(101, 101, 0, 0, 1, 4, "B") +
                           "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n1.\n*SOLID SECTION, ELSET=A, MATERIAL=M\n"
                           "*SOLID SECTION, ELSET=B, MATERIAL=M\n*SURFACE, NAME=AR\n3, S2\n6, S2\n9, S2\n"
                           "*SURFACE, NAME=BL\n101, S4\n105, S4\n109, S4\n113, S4\n*SURFACE INTERACTION, NAME=I\n"
                           "*FRICTION\n0.3\n*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nAR, BL\n"
                           "*INITIAL CONDITIONS, TYPE=VELOCITY\nAN, 1, 2.\nAN, 2, 0.5\n"
                           "*STEP, NLGEOM\n*DYNAMIC, EXPLICIT\n, 0.3\n*END STEP\n";
  const DeckRun run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const Eigen::VectorXd mass = nodal_masses(deck);
  const Momentum start = initial_momentum(run.model, mass);
  double worst_linear = 0, worst_angular = 0;
  for (const IncrementResults& r : run.recorder.results) {
    const Momentum m = momentum(r, run.model, mass);
    worst_linear = std::max(worst_linear, (m.linear - start.linear).norm());
    worst_angular = std::max(worst_angular, std::abs(m.angular - start.angular));
  }
  std::printf("mu = 0.3: worst momentum change: linear %.3g of %.3g, angular %.3g of %.3g; ALLFD %.4g\n", worst_linear,
              start.linear.norm(), worst_angular, std::abs(start.angular), run.last().energy->friction);
  EXPECT_GT(run.last().energy->friction, 0);
  EXPECT_LT(worst_linear, 1e-13 * start.linear.norm());
  EXPECT_LT(worst_angular, 1e-4 * std::abs(start.angular));  // measured 2.9e-5
}

TEST(ExplicitContact, TwoRingsCollideWithMomentumConservedToRoundOff) {
  // Two identical rings (NLGEOM, frictionless) fly at each other off centre,
  // touch, roll the contact around and part (deck: tests/analysis/decks/make_rings.py).
  const std::string path = std::string(TETHER_SOURCE_DIR) + "/tests/analysis/decks/rings.inp";
  const std::string deck = read_text(path);
  const DeckRun run = tether::testing::run_deck_file(path);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const Eigen::VectorXd mass = nodal_masses(deck);
  const Momentum start = initial_momentum(run.model, mass);
  double worst_linear = 0, worst_angular = 0, lowest_numerical = 0;
  int touching = 0;
  for (const IncrementResults& r : run.recorder.results) {
    const Momentum m = momentum(r, run.model, mass);
    worst_linear = std::max(worst_linear, (m.linear - start.linear).norm());
    worst_angular = std::max(worst_angular, std::abs(m.angular - start.angular));
    touching += r.contact[0].total_force.norm() > 0;
    lowest_numerical = std::min(lowest_numerical, r.energy->numerical);
  }
  // |p| of one ring, the scale of the linear momentum (the total is 0).
  const double ring_momentum = 0.5 * mass.sum() * 5;
  const EnergyTotals& e = *run.last().energy;
  std::printf("reports in contact %d of %zu; worst change of the linear momentum %.3g (of one ring's %.4g), of "
              "the angular %.3g (of %.4g); energy at the end: ALLKE %.6g ALLSE %.6g numerical %.4g (%.3g %% of %.6g)\n",
              touching, run.recorder.results.size(), worst_linear, ring_momentum, worst_angular, start.angular,
              e.kinetic, e.strain, e.numerical, 100 * e.numerical / run.recorder.results.front().energy->total,
              run.recorder.results.front().energy->total);
  EXPECT_GT(touching, 20);
  EXPECT_EQ(run.last().contact[0].total_force.norm(), 0);  // they have parted
  EXPECT_LT(worst_linear, 1e-13 * ring_momentum);
  EXPECT_LT(worst_angular, 1e-13 * std::abs(start.angular));
  // The kinematic impact loses energy (nodal masses stop against the master), never gains it.
  EXPECT_GE(lowest_numerical, -1e-12 * e.total);
  EXPECT_LT(e.numerical, 0.02 * run.recorder.results.front().energy->total);
}

/// The cylinder's centre of mass and mean velocity at each report (nodes of CYLN).
struct BodyMotion {
  double time = 0;
  Eigen::Vector2d centre{0, 0}, velocity{0, 0};
  double kinetic = 0, strain = 0, numerical = 0;  ///< the model's ALLKE, ALLSE, numerical energy
};
std::vector<BodyMotion> body_motion(const DeckRun& run, const Eigen::VectorXd& mass, const std::string& set) {
  std::vector<BodyMotion> out;
  for (const IncrementResults& r : run.recorder.results) {
    BodyMotion& b = out.emplace_back();
    double m = 0;
    for (int node : run.model.node_sets.at(set)) {
      const auto i = static_cast<std::size_t>(node);
      const double mi = mass[static_cast<Eigen::Index>(node)];
      b.centre += mi * (run.model.coords[i] + r.displacement[i]), b.velocity += mi * r.velocity[i], m += mi;
    }
    b.centre /= m, b.velocity /= m;
    b.time = r.step_time, b.kinetic = r.energy->kinetic, b.strain = r.energy->strain, b.numerical = r.energy->numerical;
  }
  return out;
}

TEST(ExplicitContact, CylinderSlidesInARingWithTheClosedFormSpeedAndEnergy) {
  // A cylinder (diameter 0.4 m, depth 0.1 m, rho 1000) released at rest level
  // with the centre of a fixed ring (inner diameter 1.8 m) slides down it
  // without friction under g = 9.80665: its centre falls 0.7 m, so at the
  // bottom the energy is m g 0.7 = 86.2632 J and the speed sqrt(2 g 0.7) =
  // 3.705 m/s (deck: examples/dyn_cylinder_in_ring/make_deck.py, coarse).
  const std::string path = std::string(TETHER_SOURCE_DIR) + "/tests/analysis/decks/cylinder_in_ring_coarse.inp";
  const DeckRun run = tether::testing::run_deck_file(path);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const Eigen::VectorXd mass = nodal_masses(read_text(path));
  double cylinder_mass = 0;
  for (int node : run.model.node_sets.at("CYLN")) cylinder_mass += mass[node];
  const double g = 9.80665, expected_energy = 86.2632, expected_speed = 3.705;
  EXPECT_NEAR(cylinder_mass / (1000 * M_PI * 0.04 * 0.1), 1, 1e-4);  // CPE8: the circle by parabolic arcs (5e-5)
  const std::vector<BodyMotion> motion = body_motion(run, mass, "CYLN");
  // The bottom: the centre crosses x = 0 (linear between reports).
  double speed = -1, energy = -1, time = -1, worst_numerical = 0;
  for (std::size_t k = 1; k < motion.size(); ++k) {
    worst_numerical = std::max(worst_numerical, std::abs(motion[k].numerical));
    const BodyMotion &a = motion[k - 1], &b = motion[k];
    if (speed >= 0 || a.centre.x() >= 0 || b.centre.x() < 0) continue;
    const double w = -a.centre.x() / (b.centre.x() - a.centre.x());
    speed = (1 - w) * a.velocity.norm() + w * b.velocity.norm();
    energy = (1 - w) * (a.kinetic + a.strain) + w * (b.kinetic + b.strain);
    time = (1 - w) * a.time + w * b.time;
  }
  ASSERT_GT(speed, 0) << "the cylinder did not reach the bottom";
  // A point mass on a circle of radius 0.7 from 90 degrees: a quarter of the pendulum's period, K(1/sqrt 2) sqrt(0.7 / g).
  const double quarter_period = 1.854075 * std::sqrt(0.7 / g);
  std::printf("mass %.6g kg; at the bottom (t = %.4g s, pendulum %.4g s): speed %.5g m/s (%.3g %%), ALLKE + ALLSE "
              "%.6g J (%.3g %%); largest |numerical energy| %.3g J\n",
              cylinder_mass, time, quarter_period, speed, 100 * (speed / expected_speed - 1), energy,
              100 * (energy / expected_energy - 1), worst_numerical);
  EXPECT_NEAR(speed / expected_speed, 1, 0.01);
  EXPECT_NEAR(energy / expected_energy, 1, 0.01);
  EXPECT_LT(worst_numerical, 0.01 * expected_energy);
  EXPECT_NEAR(time / quarter_period, 1, 0.01);
}

Eigen::VectorXd nodal_masses(const std::string& deck) {
  const auto b = build(deck);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(b->model.coords.size()));
  for (const auto& m : b->system->inertia()) {
    const auto dofs = m->dofs();
    for (std::size_t i = 0; i < dofs.size(); i += 2)
      out[b->discretization->dofs().node_of(dofs[i])] += m->mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
  }
  return out;
}

TEST(ExplicitContact, SoftContactIsRefusedByName) {
  std::string deck = wall_deck(4, 0.01, 1, 1e-5);
  deck.replace(deck.find("*SURFACE INTERACTION, NAME=I\n"), 29,
               "*SURFACE INTERACTION, NAME=I\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e7\n");
  const DeckRun run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("soft pressure-overclosure"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("BAREND-WALLFACE"), std::string::npos) << run.summary.message;
}

/// A 0.1 m steel square (Poisson's ratio `nu`) on a held base, friction `mu`
/// 0.3, pressed by p = 1e6 on its top and pushed sideways at its top nodes by
/// `ratio` mu p A in all, both ramped over 5 ms (quasi-static normal force).
std::string sliding_block_deck(double ratio, double nu) {
  const double mu = 0.3, p = 1e6, a = 0.1;
  return "*NODE\n1, 0, 0\n2, 0.1, 0\n3, 0.1, 0.1\n4, 0, 0.1\n11, -0.1, -0.1\n12, 0.2, -0.1\n13, 0.2, 0\n14, -0.1, 0\n"
         "*ELEMENT, TYPE=CPE4, ELSET=BLOCK\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=CPE4, ELSET=BASE\n2, 11, 12, 13, 14\n"
         "*NSET, NSET=BASEN\n11, 12, 13, 14\n*NSET, NSET=TOP\n3, 4\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, " + num(nu) +
         "\n*DENSITY\n7800.\n*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n1.\n*SOLID SECTION, ELSET=BASE, MATERIAL=STEEL\n"
         "1.\n*SURFACE, NAME=BOTTOM\n1, S1\n*SURFACE, NAME=FLOOR\n2, S3\n*SURFACE INTERACTION, NAME=I\n*FRICTION\n" +
         num(mu) + "\n*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nBOTTOM, FLOOR\n*BOUNDARY\nBASEN, 1, 2\n"
         "*STEP, AMPLITUDE=RAMP\n*DYNAMIC, EXPLICIT\n, 5e-3\n*DLOAD\n1, P3, " + num(p) + "\n*CLOAD\nTOP, 1, " +
         num(ratio * mu * p * a / 2) + "\n*END STEP\n";
}

TEST(ExplicitContact, CoulombSlipOpposesTheMotionWithMuTimesTheNormalForce) {
  // Pushed by 2 mu N(t) with N(t) = p A t / T: m v_x(T) = integral of (2 mu N - mu N) = mu p A T / 2.
  const DeckRun run = run_deck_text(sliding_block_deck(2, 0.3));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const IncrementResults& end = run.last();
  double momentum = 0;
  for (int id : {1, 2, 3, 4}) momentum += 7800 * 0.01 / 4 * end.velocity[static_cast<std::size_t>(run.node(id))].x();
  const double expected = 0.3 * 1e6 * 0.1 * 5e-3 / 2;
  std::printf("block momentum %.6g against %.6g (%.3g %%); ALLFD %.6g ALLWK %.6g numerical %.3g\n", momentum, expected,
              100 * (momentum / expected - 1), end.energy->friction, end.energy->work, end.energy->numerical);
  EXPECT_NEAR(momentum / expected, 1, 0.01);
  for (const ContactNodeValues& n : end.contact.at(0).nodes) {
    EXPECT_EQ(n.status, ContactNodeValues::Status::Slip);
    EXPECT_NEAR(std::abs(n.tangential_force), 0.3 * n.normal_force, 1e-9 * n.normal_force);
  }
  EXPECT_GT(end.energy->friction, 0.4 * end.energy->work);  // about half the work is dissipated
  EXPECT_LT(std::abs(end.energy->numerical), 2e-3 * end.energy->work);
}

TEST(ExplicitContact, BelowTheFrictionLimitTheBlockSticks) {
  const DeckRun run = run_deck_text(sliding_block_deck(0.2, 0));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  for (const IncrementResults& r : run.recorder.results)
    for (const ContactNodeValues& n : r.contact.at(0).nodes) {
      EXPECT_EQ(n.status, ContactNodeValues::Status::Stick) << "time " << r.step_time;
      EXPECT_LT(std::abs(r.displacement[static_cast<std::size_t>(n.node)].x()), 1e-15);
    }
  EXPECT_LT(std::abs(run.last().energy->friction), 1e-12 * run.last().energy->work);
}


/// The bar of bar_deck cut at node `cut` (1 < cut <= n): the right part gets
/// its own interface nodes (labels + 5000) tied to the left part's in x by *EQUATION.
std::string tied_bar_deck(int n, double h, int cut, const std::string& bc, const std::string& step) {
  std::string deck = bar_deck(n, h, bc, step);
  std::ostringstream nodes, more;
  nodes.precision(17);
  const int bottom = cut, top = n + 1 + cut;
  nodes << bottom + 5000 << ", " << (cut - 1) * h << ", 0\n" << top + 5000 << ", " << (cut - 1) * h << ", " << h << "\n";
  deck.replace(deck.find("*ELEMENT"), 8, nodes.str() + "*ELEMENT");
  more << "*NSET, NSET=ALLN\n" << bottom + 5000 << ", " << top + 5000 << "\n*NSET, NSET=INNER\n" << bottom + 5000
       << ", " << top + 5000 << "\n*EQUATION\n2\n" << bottom << ", 1, 1., " << bottom + 5000 << ", 1, -1.\n2\n" << top
       << ", 1, 1., " << top + 5000 << ", 1, -1.\n";
  // Element `cut` (the first of the right part) takes the new nodes.
  const std::string old_row = std::to_string(cut) + ", " + std::to_string(bottom) + ", " + std::to_string(bottom + 1) +
                              ", " + std::to_string(top + 1) + ", " + std::to_string(top) + "\n";
  const std::string new_row = std::to_string(cut) + ", " + std::to_string(bottom + 5000) + ", " +
                              std::to_string(bottom + 1) + ", " + std::to_string(top + 1) + ", " +
                              std::to_string(top + 5000) + "\n";
  EXPECT_NE(deck.find(old_row), std::string::npos) << old_row;
  deck.replace(deck.find(old_row), old_row.size(), new_row);
  deck.replace(deck.find("*BOUNDARY"), 9, more.str() + "*BOUNDARY");
  return deck;
}

TEST(ExplicitConstraints, ATiedBarCarriesTheWaveLikeOneBar) {
  // The tie's correction makes the two interface nodes one node of their
  // summed mass: the impact wave crosses it as if the bar were whole.
  const int n = 40, cut = 15;
  const double h = 0.01, transit = n * h / kCp;
  const std::string bc = "LEFT, 1, 1\n*INITIAL CONDITIONS, TYPE=VELOCITY\nINNER, 1, -1.\nRIGHT, 1, -1.\n";
  const std::string step = "*DYNAMIC, EXPLICIT\n, " + num(1.5 * transit) + "\n";
  const DeckRun whole = run_deck_text(bar_deck(n, h, bc, step));
  const DeckRun tied = run_deck_text(tied_bar_deck(n, h, cut, bc, step));
  ASSERT_TRUE(whole.summary.completed) << whole.summary.message;
  ASSERT_TRUE(tied.summary.completed) << tied.summary.message;
  ASSERT_EQ(whole.recorder.results.size(), tied.recorder.results.size());
  double worst = 0, multiplier = 0;
  for (std::size_t k = 0; k < whole.recorder.results.size(); ++k) {
    const IncrementResults& a = whole.recorder.results[k];
    const IncrementResults& b = tied.recorder.results[k];
    for (int id = 1; id <= 2 * n + 2; ++id) {
      worst = std::max(worst, std::abs(a.velocity[static_cast<std::size_t>(whole.node(id))].x() -
                                       b.velocity[static_cast<std::size_t>(tied.node(id))].x()));
      if (id == cut || id == n + 1 + cut)
        worst = std::max(worst, std::abs(b.velocity[static_cast<std::size_t>(tied.node(id))].x() -
                                         b.velocity[static_cast<std::size_t>(tied.node(id + 5000))].x()));
    }
    for (const MultiplierValues& m : b.multipliers)
      for (double v : m.value) multiplier = std::max(multiplier, std::abs(v));
  }
  std::printf("largest velocity difference %.3g (of v0 = 1); largest tie multiplier %.6g\n", worst, multiplier);
  EXPECT_LT(worst, 1e-9);
  // The tie carries the wave's force: half of rho c_p v0 A per node pair, at the front's passage more.
  EXPECT_GT(multiplier, 0.4 * kRho * kCp * h);
}

}  // namespace
}  // namespace tether
