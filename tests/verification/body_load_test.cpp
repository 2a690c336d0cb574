// Body loads against exact answers: a column under its own weight (GRAV) and a
// rotating annular disc in plane stress (CENTRIF).
//
// Column: width 1, height H = 10, nu = 0, base held vertically, left edge
// horizontally, gravity g down. Exact: u_y = -(rho g / E)(H y - y^2/2),
// sigma_yy = -rho g (H - y), sum of the base reactions = rho g H (unit
// thickness). CPS8 represents the quadratic u_y exactly; CPS4 is exact at the
// nodes (the problem is one-dimensional, and 1D linear elements with
// consistent loads are nodally exact).
//
// Disc: a quarter of the annulus a = 2 <= r <= b = 10 (symmetry on both
// straight edges), CPS8 on a polar grid with mid-side nodes on the circles,
// spinning at omega about z (Timoshenko & Goodier, rotating disc with a hole):
//   sigma_r  = (3 + nu)/8 rho omega^2 (b^2 + a^2 - a^2 b^2 / r^2 - r^2)
//   sigma_th = (3 + nu)/8 rho omega^2 (b^2 + a^2 + a^2 b^2 / r^2 - (1 + 3 nu)/(3 + nu) r^2)
//   u_r = r (sigma_th - nu sigma_r) / E.
// Its tolerances are the measured errors rounded up (the circles are
// approximated by the quadratic edges; both errors fall with the mesh size).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "analysis/run_deck.hpp"
#include "support/block_mesh.hpp"

using namespace tether;
using tether::testing::Block;

namespace {

constexpr double kE = 1000, kRho = 2, kG = 5, kHeight = 10;

std::string column_deck(bool quadratic, int ny) {
  const Block b{0, 1, 0, kHeight, 2, ny, quadratic, 1, 1, "COLUMN"};
  std::ostringstream d;
  b.write(d);
  d << "*NSET, NSET=BASE\n";
  for (int i = 0; i <= b.nx * b.step(); ++i) d << b.grid(i, 0) << "\n";
  d << "*NSET, NSET=LEFT\n";
  for (int j = 0; j <= b.ny * b.step(); ++j) d << b.grid(0, j) << "\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << kE << ", 0\n*DENSITY\n" << kRho << "\n"
    << "*SOLID SECTION, ELSET=COLUMN, MATERIAL=M\n1.\n*BOUNDARY\nBASE, 2, 2\nLEFT, 1, 1\n"
    << "*STEP\n*STATIC\n*DLOAD\nCOLUMN, GRAV, " << kG << ", 0, -1, 0\n*END STEP\n";
  std::string text = d.str();
  for (auto pos = text.find("CPE"); pos != std::string::npos; pos = text.find("CPE", pos)) text.replace(pos, 3, "CPS");
  return text;
}

double exact_uy(double y) { return -kRho * kG / kE * (kHeight * y - y * y / 2); }

void check_column(bool quadratic, int ny) {
  const auto run = tether::testing::run_deck_text(column_deck(quadratic, ny));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& res = run.last();
  double max_u = 0;
  for (int n = 0; n < run.model.n_nodes(); ++n) {
    const Eigen::Vector2d x = run.model.coords[static_cast<std::size_t>(n)];
    max_u = std::max(max_u, std::abs(exact_uy(x.y())));
    EXPECT_NEAR(res.displacement[static_cast<std::size_t>(n)].y(), exact_uy(x.y()), 1e-10 * std::abs(exact_uy(kHeight)))
        << "node " << run.model.node_ids[static_cast<std::size_t>(n)] << " at y = " << x.y();
    EXPECT_NEAR(res.displacement[static_cast<std::size_t>(n)].x(), 0, 1e-12);
  }
  EXPECT_NEAR(run.reaction_sum("BASE", 1), kRho * kG * kHeight, 1e-10 * kRho * kG * kHeight);
  if (!quadratic) return;
  for (const auto& element : res.points)
    for (const PointValues& p : element) {
      double y = p.x.y();  // the point's reference height: y + u_y(y) = current height
      for (int k = 0; k < 60; ++k) y = p.x.y() - exact_uy(y);
      EXPECT_NEAR(p.stress[1], -kRho * kG * (kHeight - y), 1e-9 * kRho * kG * kHeight) << "at y = " << y;
    }
}

constexpr double kA = 2, kB = 10, kNu = 0.3, kDiscE = 200000, kDiscRho = 7.8e-9, kOmega2 = 1e6;

double sigma_r(double r) {
  return (3 + kNu) / 8 * kDiscRho * kOmega2 * (kB * kB + kA * kA - kA * kA * kB * kB / (r * r) - r * r);
}
double sigma_theta(double r) {
  return (3 + kNu) / 8 * kDiscRho * kOmega2 *
         (kB * kB + kA * kA + kA * kA * kB * kB / (r * r) - (1 + 3 * kNu) / (3 + kNu) * r * r);
}
double exact_ur(double r) { return r * (sigma_theta(r) - kNu * sigma_r(r)) / kDiscE; }

/// Quarter annulus of nr x nt CPS8 on a polar grid; node (i, j) at radius
/// index i (0..2 nr) and angle index j (0..2 nt), labels 1 + j (2 nr + 1) + i.
std::string disc_deck(int nr, int nt) {
  const int mr = 2 * nr, mt = 2 * nt;
  const auto label = [&](int i, int j) { return 1 + j * (mr + 1) + i; };
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n";
  for (int j = 0; j <= mt; ++j)
    for (int i = 0; i <= mr; ++i) {
      if (i % 2 == 1 && j % 2 == 1) continue;
      const double r = kA + (kB - kA) * i / mr, t = std::numbers::pi / 2 * j / mt;
      d << label(i, j) << ", " << r * std::cos(t) << ", " << r * std::sin(t) << "\n";
    }
  d << "*ELEMENT, TYPE=CPS8, ELSET=DISC\n";
  for (int ej = 0; ej < nt; ++ej)
    for (int ei = 0; ei < nr; ++ei) {
      const int i = 2 * ei, j = 2 * ej;
      d << 1 + ej * nr + ei << ", " << label(i, j) << ", " << label(i + 2, j) << ", " << label(i + 2, j + 2) << ", "
        << label(i, j + 2) << ", " << label(i + 1, j) << ", " << label(i + 2, j + 1) << ", " << label(i + 1, j + 2)
        << ", " << label(i, j + 1) << "\n";
    }
  d << "*NSET, NSET=XAXIS\n";
  for (int i = 0; i <= mr; ++i) d << label(i, 0) << "\n";
  d << "*NSET, NSET=YAXIS\n";
  for (int i = 0; i <= mr; ++i) d << label(i, mt) << "\n";
  d << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << kDiscE << ", " << kNu << "\n*DENSITY\n" << kDiscRho << "\n"
    << "*SOLID SECTION, ELSET=DISC, MATERIAL=STEEL\n0.5\n*BOUNDARY\nXAXIS, 2, 2\nYAXIS, 1, 1\n"
    << "*STEP\n*STATIC\n*DLOAD\nDISC, CENTRIF, " << kOmega2 << ", 0, 0, 0, 0, 0, 1\n*END STEP\n";
  return d.str();
}

}  // namespace

TEST(BodyLoadVerification, ColumnUnderItsOwnWeightIsExact) {
  check_column(true, 4);
  check_column(false, 10);
}

TEST(BodyLoadVerification, RotatingDiscMatchesTheClosedForm) {
  const auto run = tether::testing::run_deck_text(disc_deck(8, 8));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& res = run.last();
  double u_error = 0, hoop_error = 0;
  for (int n = 0; n < run.model.n_nodes(); ++n) {
    const Eigen::Vector2d x = run.model.coords[static_cast<std::size_t>(n)];
    const double ur = res.displacement[static_cast<std::size_t>(n)].dot(x.normalized());
    u_error = std::max(u_error, std::abs(ur / exact_ur(x.norm()) - 1));
  }
  for (const auto& element : res.points)
    for (const PointValues& p : element) {
      const Eigen::Vector2d e = p.x.normalized();
      const double hoop = p.stress[0] * e.y() * e.y() + p.stress[1] * e.x() * e.x() - 2 * p.stress[3] * e.x() * e.y();
      hoop_error = std::max(hoop_error, std::abs(hoop - sigma_theta(p.x.norm())) / sigma_theta(kA));
    }
  std::printf("rotating disc, CPS8 8x8: max |u_r/exact - 1| = %.2e, max hoop stress error / sigma_theta(a) = %.2e\n",
              u_error, hoop_error);
  // Measured: 4.2e-4 and 6.9e-3 (4x4: 4.2e-3, 1.8e-2; 16x16: 3.2e-5, 2.2e-3).
  EXPECT_LT(u_error, 6e-4);
  EXPECT_LT(hoop_error, 1e-2);
}
