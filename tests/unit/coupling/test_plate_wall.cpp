// The plate's faces in the SPH sums (src/sph/plate_wall.cpp, docs/coupling.md section 12): the ghosts must stand
// exactly for what the plate takes out of a particle's kernel support, beside a face, above the top and round a
// corner alike. Checked on the paper's geometry (dx 1.5 mm, plate 3 mm x 8 cm, 2 x 60 Q9 surface) with the water
// lattice the fluid starts from: the kernel sum over the real water the particle sees (pairs crossing the plate's
// mid-line dropped) plus the ghosts must be a partition of unity, and the first moment (the pressure force at
// uniform pressure) must vanish.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "halfeti/sph/kernel.hpp"
#include "halfeti/sph/neighbour_list.hpp"
#include "halfeti/sph/plate_wall.hpp"

namespace halfeti::sph {
namespace {

// The paper's faces lie on lattice lines at dx 1.5 mm (99 and 101 dx); its top at 80 mm does not (53.33 dx), and the
// lattice then sees the top at 79.5 mm (LatticeOffsets::top = -0.5 mm).
constexpr double kDx = 0.0015, kLeft = 0.1485, kRight = 0.1515;

PlateOutline paper_outline(double kTop) {
  PlateOutline o;
  auto add = [&](double x, double y) {
    o.x.push_back(x);
    o.y.push_back(y);
  };
  for (int k = 0; k <= 120; ++k) add(kRight, kTop * k / 120.0);                 // up the right face
  for (int j = 1; j <= 4; ++j) add(kRight - j * (kRight - kLeft) / 4.0, kTop);  // across the top
  for (int k = 119; k >= 0; --k) add(kLeft, kTop * k / 120.0);                  // down the left face
  o.vx.assign(o.size(), 0.0);
  o.vy.assign(o.size(), 0.0);
  o.ax.assign(o.size(), 0.0);
  o.ay.assign(o.size(), 0.0);
  return o;
}

struct Sums {
  double w = 0.0, gx = 0.0, gy = 0.0;  // sum V W, sum V grad W
};

class PlateWallSupport : public ::testing::Test {
 protected:
  void SetUp() override { build(0.0795, 0.0); }  // a top on a lattice line: no offset

  // The plate of height `top`, seen by the lattice with its top moved by `offset`.
  void build(double top, double offset) {
    kernel_ = Kernel{KernelKind::kCubicSpline, 1.33 * kDx, 1.0};  // h = 1.33 dx (paper, Table 1)
    top_ = top;
    outline_ = paper_outline(top);
    wall_.set_offsets({0.0, 0.0, offset});
    wall_.set_outline(outline_, kDx, kernel_.support());
    mid_ = wall_.midline();
    wx_.clear();
    wy_.clear();
    for (int j = 0; j < 66;
         ++j)  // water lattice 0.3 m x 0.1 m, the plate's place (as the lattice sees it) empty
      for (int i = 0; i < 200; ++i) {
        const double x = (i + 0.5) * kDx, y = (j + 0.5) * kDx;
        if (x > kLeft && x < kRight && y < top + offset) continue;
        wx_.push_back(x);
        wy_.push_back(y);
      }
  }

  // Kernel sums for the particle at lattice point (x, y): real water seen plus the plate-wall ghosts.
  Sums sums(double x, double y) {
    Sums s;
    const KernelEvaluator ke(kernel_);
    auto add = [&](double xj, double yj, double vol) {
      const double ex = xj - x, ey = yj - y, r = std::hypot(ex, ey);
      if (r >= kernel_.support()) return;
      double w, f;
      ke(r, w, f);
      s.w += vol * w;
      s.gx += vol * f * (x - xj);  // grad_i W = F (x_i - x_j)
      s.gy += vol * f * (y - yj);
    };
    for (std::size_t j = 0; j < wx_.size(); ++j) {
      bool cut = false;
      for (const auto& b : mid_) cut = cut || segments_cross(x, y, wx_[j], wy_[j], b.xa, b.ya, b.xb, b.yb);
      if (!cut) add(wx_[j], wy_[j], kDx * kDx);
    }
    wall_.find_pairs(&x, &y, 1, kernel_);
    if (!wall_.particles().empty())
      for (int g : wall_.ghosts_of(0)) add(wall_.ghost_x(g), wall_.ghost_y(g), wall_.ghost_volume(g));
    return s;
  }

  void scan_near_the_top();

  // The same sums for a particle far from the plate (the lattice's own quadrature error).
  Sums bulk() { return sums(0.05 + 0.5 * kDx, 0.05 + 0.5 * kDx); }

  Kernel kernel_;
  double top_ = 0.0;
  PlateOutline outline_;
  PlateWall wall_;
  std::vector<Barrier> mid_;
  std::vector<double> wx_, wy_;
};

TEST_F(PlateWallSupport, GhostsCompleteTheSupportBesideAFaceAboveTheTopAndRoundACorner) {
  const Sums ref = bulk();
  // A single missing lattice neighbour at distance dx changes sum V W by dx^2 W(dx) ~ 0.12, and dx times the
  // gradient sum by about as much: the tolerances below are a small fraction of one neighbour.
  const double w_dx = [&] {
    double w, f;
    const KernelEvaluator ke(kernel_);
    ke(kDx, w, f);
    return kDx * kDx * w;
  }();
  struct Case {
    const char* where;
    double x, y;
  };
  // Lattice points (i + 1/2) dx; the plate spans x 0.1485-0.1515, y 0-0.0795 (row 53 at 80.25 mm is the first
  // above the top).
  const Case cases[] = {
      {"beside the right face, mid-height", 0.15225, 0.04125},
      {"second row off the left face, low", 0.14625, 0.00975},
      {"beside the right face, just below the top", 0.15225, 0.07875},
      {"beside the left face, second row below the top", 0.14775, 0.07725},
      {"above the top, first row", 0.14925, 0.08025},
      {"above the top, second row", 0.15075, 0.08175},
      {"in the corner's wedge", 0.15225, 0.08025},
      {"diagonally off the left corner", 0.14625, 0.08175},
  };
  for (const Case& c : cases) {
    const Sums s = sums(c.x, c.y);
    SCOPED_TRACE(c.where);
    // Sum V W and the first moment: the lattice's own values within a thirtieth of one neighbour's share (the
    // ghosts continue the lattice, so only the faces' and corners' geometry is left to differ).
    EXPECT_NEAR(s.w, ref.w, w_dx / 30.0) << "sum V W = " << s.w << " (bulk " << ref.w << ")";
    const double g = std::hypot(s.gx - ref.gx, s.gy - ref.gy);
    EXPECT_LT(g * kDx, w_dx / 30.0) << "sum V grad W = (" << s.gx << ", " << s.gy << ") /m";
  }
}

// All water lattice points within 6 mm of the plate's top corners: the worst sum and first moment (dx times the
// gradient sum), both within 0.004, a thirtieth of one neighbour's share w_dx ~ 0.12. Before the ghosts were laid in
// lattice rows, the previous layout (rows behind each face, a particle seeing only its closest face's) gave 0.0046 and
// 0.0088 for this top.
TEST_F(PlateWallSupport, EveryLatticePointNearTheTopSeesACompleteSupport) {
  scan_near_the_top();
}

TEST_F(PlateWallSupport, ThePapersTopOffTheLatticeIsSeenAtTheNearestLatticeLine) {
  build(0.08, -0.0005);  // 80 mm = 53.33 dx: the lattice sees 79.5 mm
  EXPECT_NEAR(wall_.midline().back().yb, 0.0795, 1e-12);
  EXPECT_NEAR(wall_.outline().y[wall_.outline().size() / 2], 0.0795, 1e-12);
  scan_near_the_top();
}

void PlateWallSupport::scan_near_the_top() {
  const double kTop = top_;
  const Sums ref = bulk();
  double worst_w = 0.0, worst_g = 0.0, at_w[2] = {0, 0}, at_g[2] = {0, 0};
  for (std::size_t j = 0; j < wx_.size(); ++j) {
    const double dl = std::hypot(wx_[j] - kLeft, wy_[j] - kTop),
                 dr = std::hypot(wx_[j] - kRight, wy_[j] - kTop);
    if (std::min(dl, dr) > 0.006) continue;
    const Sums s = sums(wx_[j], wy_[j]);
    const double ew = std::abs(s.w - ref.w), eg = std::hypot(s.gx - ref.gx, s.gy - ref.gy) * kDx;
    if (ew > worst_w) worst_w = ew, at_w[0] = wx_[j], at_w[1] = wy_[j];
    if (eg > worst_g) worst_g = eg, at_g[0] = wx_[j], at_g[1] = wy_[j];
  }
  std::printf(
      "near the top: worst |sum V W - bulk| = %.4f at (%.5f, %.5f); worst dx |sum V grad W| = %.4f at "
      "(%.5f, %.5f)\n",
      worst_w, at_w[0], at_w[1], worst_g, at_g[0], at_g[1]);
  EXPECT_LT(worst_w, 0.004);
  EXPECT_LT(worst_g, 0.004);
}

TEST(PlateWallOffsets, ABentPlatesTopSlidesAlongItsFaces) {
  // The paper's plate bent as x += c y^2 (tip 30 mm to the right), its top lowered by half a spacing: the corners
  // slide 0.5 mm down their faces, so the top's middle moves 0.5 mm along the bent plate, and the faces keep
  // pairing up (the layout is built without error).
  PlateOutline o = paper_outline(0.08);
  const double c = 0.03 / (0.08 * 0.08);
  for (std::size_t k = 0; k < o.size(); ++k) o.x[k] += c * o.y[k] * o.y[k];
  PlateWall wall;
  wall.set_offsets({0.0, 0.0, -0.0005});
  const Kernel kernel{KernelKind::kCubicSpline, 1.33 * kDx, 1.0};
  ASSERT_NO_THROW(wall.set_outline(o, kDx, kernel.support()));
  const auto& m = wall.midline();
  const double tx = 0.15 + c * 0.08 * 0.08, ty = 0.08;  // the true top's middle
  const double moved = std::hypot(m.back().xb - tx, m.back().yb - ty);
  EXPECT_NEAR(moved, 0.0005, 0.02 * 0.0005) << "the top's middle moved by " << moved << " m";
  EXPECT_GT(wall.ghost_count(), 0u);
}

TEST(PlateWallRows, ReachTheFootOfBothFacesOfABentPlate) {
  // The paper's plate (79.5 mm as the lattice sees it, 53 dx; 3 mm thick) bent into a circular arc that turns its top
  // by 0.8 rad to the right: the right face (inside the bend) is 1.2 mm shorter than the mid-line (52.2 dx), the
  // left 1.2 mm longer (54.6 dx). The ghosts must stand for the whole solid down to the clamp on both faces: the
  // solid's ghost volume is the plate's area L t (an annular sector's area theta R t), and the lowest solid ghost
  // sits half a row above the foot. (Rows a fixed dx apart, as many as the shorter face holds, stopped 52 rows down:
  // their lowest points 0.7 dx above the inner face's foot and 3.1 dx above the outer one's.)
  constexpr double kLength = 0.0795, kThick = 0.003, kTurn = 0.8, kR = kLength / kTurn;
  PlateOutline o;
  auto add = [&](double s,
                 double side) {  // side +1: the right face, -1: the left, at arc length s of the mid-line
    const double phi = s / kR;
    o.x.push_back(0.15 + kR * (1.0 - std::cos(phi)) + side * 0.5 * kThick * std::cos(phi));
    o.y.push_back(kR * std::sin(phi) - side * 0.5 * kThick * std::sin(phi));
  };
  for (int k = 0; k <= 120; ++k) add(kLength * k / 120.0, 1.0);
  for (int j = 1; j <= 3; ++j) add(kLength, 1.0 - 2.0 * j / 4.0);  // across the top
  for (int k = 120; k >= 0; --k) add(kLength * k / 120.0, -1.0);
  for (auto* v : {&o.vx, &o.vy, &o.ax, &o.ay}) v->assign(o.size(), 0.0);
  PlateWall wall;
  const Kernel kernel{KernelKind::kCubicSpline, 1.33 * kDx, 1.0};
  wall.set_outline(o, kDx, kernel.support());
  double solid = 0.0, lowest = 1.0;
  for (int g = 0; g < static_cast<int>(wall.ghost_count()); ++g)
    if (wall.ghost_in_solid(g)) {
      solid += wall.ghost_volume(g);
      lowest = std::min(lowest, wall.ghost_y(g));
    }
  // The body ghosts are quadrature points of the plate's area: the chords of the 120-segment faces and the rows'
  // straight cuts across a bent plate differ from the arc's area by less than 1e-3 of it.
  EXPECT_NEAR(solid, kLength * kThick, 1e-3 * kLength * kThick);
  // 53 rows down faces of 52.2 and 54.6 dx: the foot row's points half a row (0.49 and 0.52 dx) above the clamp,
  // its ghosts between them, so no higher than 0.52 dx.
  EXPECT_LT(lowest, 0.53 * kDx) << "the lowest solid ghost is " << lowest / kDx << " dx above the floor";
}

// The paper's kernel (h = 1.33 dx) and its plate standing in the tank (top on a lattice line), as a wall.
Kernel paper_kernel() {
  return Kernel{KernelKind::kCubicSpline, 1.33 * kDx, 1.0};
}
PlateWall paper_wall(const Kernel& kernel) {
  PlateWall wall;
  wall.set_outline(paper_outline(0.0795), kDx, kernel.support());
  return wall;
}

// The constants of the repulsion tests: the tank walls' repulsion (fluid.wall_repulsion 0.01, c0 20 m/s, range dx/2)
// in a 0.3 m x 0.2 m tank.
PlateWallConstants repulsion_constants(const Kernel& kernel) {
  PlateWallConstants k;
  k.dx = kDx;
  k.h = kernel.h;
  k.rho0 = 1000.0;
  k.c0 = 20.0;
  k.wall_amplitude = 0.01 * k.c0 * k.c0 / k.h;
  k.wall_range = 0.5 * kDx;
  k.tank_length = 0.3;
  k.tank_height = 0.2;
  return k;
}

TEST(PlateWallRepulsion, AsTheTankWallsWithinHalfASpacingOfAFaceAndTheOppositeOnThePlate) {
  // Water in still state (p = 0, at rest, no body force) so that only the faces' repulsion acts: a particle within
  // dx/2 of a face must get the tank walls' Monaghan & Kos push A (1 - q) / sqrt(q), q = d / (dx/2), along the
  // normal from its closest point (walls.cpp's profile summed along a continuous wall is one), none from dx/2 on,
  // and the plate the opposite force, shared by the segment's two points. Beside the right face, above the top and
  // at the foot's corner with the floor (pushed out of the face, not into the floor).
  const Kernel kernel = paper_kernel();
  PlateWall wall = paper_wall(kernel);
  const PlateWallConstants k = repulsion_constants(kernel);
  struct Case {
    double x, y, nx, ny, d;
  };
  std::vector<Case> cases;
  for (double d : {0.0, 0.05, 0.25, 0.49, 0.5, 0.7}) {
    cases.push_back({kRight + d * kDx, 0.04, 1.0, 0.0, d * kDx});    // beside the right face
    cases.push_back({0.15, 0.0795 + d * kDx, 0.0, 1.0, d * kDx});    // above the top
    cases.push_back({kLeft - d * kDx, 0.0007, -1.0, 0.0, d * kDx});  // the left foot, 0.47 dx above the floor
  }
  for (const Case& c : cases) {
    const double vx = 0.0, vy = 0.0, rho = 1000.0, p = 0.0, mass = 1000.0 * kDx * kDx;
    const std::int64_t gid = 7;
    double ax = 0.0, ay = 0.0;
    wall.find_pairs(&c.x, &c.y, 1, kernel);
    ASSERT_EQ(wall.particles().size(), 1u) << "a particle " << c.d / kDx << " dx from the plate has ghosts";
    wall.momentum(&vx, &vy, &rho, &p, &mass, &gid, k, &ax, &ay);
    const double q = std::max(c.d / k.wall_range, 1e-3);
    const double expected = q < 1.0 ? k.wall_amplitude * (1.0 - q) / std::sqrt(q) : 0.0;
    const std::string where = "at (" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
    EXPECT_NEAR(ax, expected * c.nx, 1e-12 * k.wall_amplitude) << where;
    EXPECT_NEAR(ay, expected * c.ny, 1e-12 * k.wall_amplitude) << where;
    double fx = 0.0, fy = 0.0;
    for (const auto& l : wall.loads()) {
      fx += l.fx;
      fy += l.fy;
    }
    EXPECT_NEAR(fx, -mass * ax, 1e-12 * mass * k.wall_amplitude) << where;
    EXPECT_NEAR(fy, -mass * ay, 1e-12 * mass * k.wall_amplitude) << where;
  }
}

TEST(PlateWallRepulsion, PushesNoParticleIntoTheFloor) {
  // The paper's plate hanging with its free end 1 mm (2/3 dx) above the floor, as the Antoci gate's: a particle in the
  // gap, 0.4 mm under the end, is within dx/2 of the plate and of the floor. The end's push (down) would drive it into
  // the floor against the floor's own repulsion; within one spacing of the floor that part is the floor's, so the
  // particle gets none, and neither does the plate.
  PlateOutline up = paper_outline(0.0795), o;
  for (std::size_t k = up.size();
       k-- > 0;) {  // mirrored about y = 0.0805 / 2 and reversed: outward stays outward
    o.x.push_back(up.x[k]);
    o.y.push_back(0.0805 - up.y[k]);
  }
  for (auto* v : {&o.vx, &o.vy, &o.ax, &o.ay}) v->assign(o.size(), 0.0);
  PlateWall wall;
  const Kernel kernel{KernelKind::kCubicSpline, 1.33 * kDx, 1.0};
  wall.set_outline(o, kDx, kernel.support());
  const PlateWallConstants k = repulsion_constants(kernel);
  const double vx = 0.0, vy = 0.0, rho = 1000.0, p = 0.0, mass = 1000.0 * kDx * kDx;
  const std::int64_t gid = 3;
  for (double y : {0.0003, 0.0006}) {  // in the gap, 0.7 and 0.4 mm under the end (within dx/2 of it)
    const double x = 0.15;
    double ax = 0.0, ay = 0.0;
    wall.find_pairs(&x, &y, 1, kernel);
    ASSERT_EQ(wall.particles().size(), 1u);
    wall.momentum(&vx, &vy, &rho, &p, &mass, &gid, k, &ax, &ay);
    EXPECT_EQ(ax, 0.0) << "y = " << y;
    EXPECT_EQ(ay, 0.0) << "y = " << y;
  }
  // The same plate and particle 0.5 m up, far from the floor: pushed down (q = 0.53: A 0.47 / sqrt(0.53) = 0.64 A),
  // so the check above can fail.
  PlateOutline raised = o;
  for (double& yy : raised.y) yy += 0.5;
  wall.set_outline(raised, kDx, kernel.support());
  const double x = 0.15, y = 0.5006;
  double ax = 0.0, ay = 0.0;
  wall.find_pairs(&x, &y, 1, kernel);
  ASSERT_EQ(wall.particles().size(), 1u);
  wall.momentum(&vx, &vy, &rho, &p, &mass, &gid, k, &ax, &ay);
  EXPECT_LT(ay, -0.5 * k.wall_amplitude);
}

TEST(PlateWallFreeSurface, AParticleMarkedAtAFreeSurfacePushesTheFaceButNeverPullsIt) {
  // A particle 0.8 dx beside the right face (beyond the repulsion's dx/2, at rest, no body force): only the ghosts'
  // pressure term acts. In tension it is pulled towards the face and the face towards it, unless marked as at a
  // free surface, where the term is zero; in compression it is pushed away alike, marked or not.
  const Kernel kernel = paper_kernel();
  PlateWall wall = paper_wall(kernel);
  const PlateWallConstants k = repulsion_constants(kernel);
  const double x = kRight + 0.8 * kDx, y = 26.5 * kDx, vx = 0.0, vy = 0.0, rho = 1000.0,
               mass = 1000.0 * kDx * kDx;
  const std::int64_t gid = 5;
  auto force = [&](double p, bool marked, double& ax, double& plate_fx) {
    ax = 0.0;
    double ay = 0.0;
    wall.find_pairs(&x, &y, 1, kernel);
    EXPECT_EQ(wall.particles().size(), 1u);
    if (marked) wall.set_free_surface({1});
    wall.momentum(&vx, &vy, &rho, &p, &mass, &gid, k, &ax, &ay);
    EXPECT_NEAR(ay, 0.0,
                1e-9 * std::abs(ax) + 1e-12);  // on a lattice row beside a straight face: normal only
    plate_fx = 0.0;
    for (const auto& l : wall.loads()) plate_fx += l.fx;
  };
  double ax = 0.0, fx = 0.0;
  force(-1.0e5, false, ax, fx);
  EXPECT_LT(ax, 0.0) << "in tension and not marked: pulled towards the face";
  EXPECT_GT(fx, 0.0) << "and the face towards the particle";
  force(-1.0e5, true, ax, fx);
  EXPECT_EQ(ax, 0.0) << "marked: no pull";
  EXPECT_EQ(fx, 0.0);
  double ax_marked = 0.0, fx_marked = 0.0;
  force(1.0e5, false, ax, fx);
  force(1.0e5, true, ax_marked, fx_marked);
  EXPECT_GT(ax, 0.0) << "in compression: pushed off the face";
  EXPECT_EQ(ax_marked, ax);
  EXPECT_EQ(fx_marked, fx);
}

TEST(PlateWallFreeSurface, AParticleMarkedAtAFreeSurfaceLeavingTheFaceDoesNotExpand) {
  // The same particle moving off the face at 1 m/s: the ghosts' continuity term (eq. 3, velocity mirrored) lowers
  // its density unless it is marked, when the gap it leaves is the air's; moving onto the face it is compressed
  // alike, marked or not.
  const Kernel kernel = paper_kernel();
  PlateWall wall = paper_wall(kernel);
  const double x = kRight + 0.8 * kDx, y = 26.5 * kDx, vy = 0.0, rho = 1000.0;
  auto rate = [&](double vx, bool marked) {
    wall.find_pairs(&x, &y, 1, kernel);
    EXPECT_EQ(wall.particles().size(), 1u);
    if (marked) wall.set_free_surface({1});
    double drho = 0.0;
    wall.continuity(&vx, &vy, &rho, &drho);
    return drho;
  };
  EXPECT_LT(rate(1.0, false), 0.0) << "leaving the face, not marked: expands";
  EXPECT_EQ(rate(1.0, true), 0.0) << "marked: does not";
  EXPECT_GT(rate(-1.0, false), 0.0) << "onto the face: compressed";
  EXPECT_EQ(rate(-1.0, true), rate(-1.0, false));
}

TEST(PlateWallLaminar, DampsOnlyTheMotionRelativeToTheFaceAlongItsNormalAndThePlateTakesTheReaction) {
  // The laminar viscous term over the face ghosts (fluid.laminar_viscosity, Morris et al. 1997) with the ghosts'
  // velocity mirrored about the face (free slip, as the tank walls' without wall_no_slip): a particle 0.8 dx beside
  // the right face (beyond the repulsion's dx/2, p = 0, no body force, no artificial viscosity) moving towards it
  // and along it must be slowed in its motion towards the face only, in proportion to nu; the same motion with the
  // plate moving alike (the particle at rest relative to the face) gets nothing; the plate takes the opposite force.
  const Kernel kernel = paper_kernel();
  PlateWall wall = paper_wall(kernel);
  PlateWallConstants k = repulsion_constants(kernel);
  const double x = kRight + 0.8 * kDx, y = 26.5 * kDx, rho = 1000.0, p = 0.0, mass = 1000.0 * kDx * kDx;
  const double vx = -1.0, vy = 0.3;  // towards the face and up along it [m/s]
  const std::int64_t gid = 9;
  auto force = [&](double nu, double& ax, double& ay, double& plate_fx, double& plate_fy) {
    k.laminar_nu = nu;
    ax = ay = 0.0;
    wall.find_pairs(&x, &y, 1, kernel);
    EXPECT_EQ(wall.particles().size(), 1u);
    wall.momentum(&vx, &vy, &rho, &p, &mass, &gid, k, &ax, &ay);
    plate_fx = plate_fy = 0.0;
    for (const auto& l : wall.loads()) {
      plate_fx += l.fx;
      plate_fy += l.fy;
    }
  };
  double ax0, ay0, fx0, fy0, ax1, ay1, fx1, fy1, ax2, ay2, fx2, fy2;
  force(0.0, ax0, ay0, fx0, fy0);
  EXPECT_EQ(ax0, 0.0) << "without the term nothing acts here (the check below can fail)";
  EXPECT_EQ(ay0, 0.0);
  force(1.0e-3, ax1, ay1, fx1, fy1);
  force(2.0e-3, ax2, ay2, fx2, fy2);
  EXPECT_GT(ax1, 0.0) << "the approach towards the face (-x) is slowed";
  EXPECT_NEAR(ay1, 0.0, 1e-9 * ax1) << "free slip: the motion along the face is not damped";
  EXPECT_NEAR(ax2, 2.0 * ax1, 1e-12 * ax1) << "in proportion to nu";
  EXPECT_NEAR(fx1, -mass * ax1, 1e-12 * mass * ax1) << "the plate takes the reaction";
  EXPECT_NEAR(fy1, -mass * ay1, 1e-12 * mass * ax1);
  // A damping rate of about nu / dx^2 (1e-3 / 2.25e-6 = 440 1/s) times the 1 m/s approach, within a decade either
  // way: a term of the wrong size (a missing r^2 or V_g) lands far outside.
  EXPECT_GT(ax1, 0.1 * 1.0e-3 / (kDx * kDx));
  EXPECT_LT(ax1, 10.0 * 1.0e-3 / (kDx * kDx));
  // The plate moving with the particle: no relative motion, no force.
  PlateOutline moving = paper_outline(0.0795);
  moving.vx.assign(moving.size(), vx);
  moving.vy.assign(moving.size(), vy);
  wall.set_outline(moving, kDx, kernel.support());
  force(1.0e-3, ax1, ay1, fx1, fy1);
  EXPECT_NEAR(ax1, 0.0, 1e-12);
  EXPECT_NEAR(ay1, 0.0, 1e-12);
}

}  // namespace
}  // namespace halfeti::sph
