#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "core/surface/pratt_fit.hpp"
#include "core/math/weight.hpp"

using namespace amls;

namespace {

template <int D>
PrattFit<D> fit_around(const Vec<D>& p, const std::vector<Vec<D>>& neighbours, double radius) {
  PrattFit<D> fit;
  for (const Vec<D>& q : neighbours) {
    const Vec<D> u = (q - p) / radius;
    fit.add(u, weight_of_squared_ratio(u.squaredNorm()));
  }
  return fit;
}

// The Pratt normal straight from its definition: the eigenvector of
// A alpha = lambda C alpha with the smallest non-negative lambda, by Eigen's
// general eigensolver, with A summed here.
template <int D>
Vec<D> reference_normal(const Vec<D>& p, const std::vector<Vec<D>>& neighbours, double radius, const Vec<D>& carried) {
  constexpr int M = D + 2;
  Eigen::Matrix<double, M, M> a = Eigen::Matrix<double, M, M>::Zero();
  for (const Vec<D>& q : neighbours) {
    const Vec<D> u = (q - p) / radius;
    Eigen::Matrix<double, M, 1> basis;
    basis << 1.0, u, u.squaredNorm();
    a += weight_of_squared_ratio(u.squaredNorm()) * basis * basis.transpose();
  }
  Eigen::Matrix<double, M, M> c = Eigen::Matrix<double, M, M>::Identity();
  c(0, 0) = c(M - 1, M - 1) = 0.0;
  c(0, M - 1) = c(M - 1, 0) = -2.0;
  const Eigen::EigenSolver<Eigen::Matrix<double, M, M>> solver(c.inverse() * a);
  double best = std::numeric_limits<double>::infinity();
  Vec<D> normal = Vec<D>::Zero();
  for (int k = 0; k < M; ++k) {
    const double lambda = solver.eigenvalues()[k].real();
    const Eigen::Matrix<double, M, 1> x = solver.eigenvectors().col(k).real();
    if (lambda < -1e-9 || lambda >= best || !(x.dot(c * x) > 0.0)) continue;
    best = lambda;
    normal = x.template segment<D>(1).normalized();
  }
  return normal.dot(carried) < 0.0 ? Vec<D>(-normal) : normal;
}

// Noisy samples of a circle of radius r about the origin, within `spread` of angle 0.
std::vector<Vec<2>> noisy_arc(double r, double spread, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-spread, spread), offset(-noise, noise);
  std::vector<Vec<2>> pts{Vec<2>(r, 0.0)};
  for (int i = 0; i < 60; ++i) {
    const double t = angle(rng);
    pts.push_back((r + offset(rng)) * Vec<2>(std::cos(t), std::sin(t)));
  }
  return pts;
}

// A lane of a batch: its neighbourhood about pts[0], carried normal and expected status.
struct Lane {
  std::vector<Vec<2>> pts;
  Vec<2> carried;
  FitStatus expected = FitStatus::ok;
};

// Solves the lanes as one batch, and each alone; every lane must get the same
// bits both ways, and agree with the eigensolver's normal where it succeeds.
void check_batch_against_alone(const std::vector<Lane>& lanes) {
  constexpr double kRadius = 0.05;
  std::vector<PrattFit<2>> fits;
  std::vector<Vec<2>> carried, normals;
  for (const Lane& lane : lanes) {
    fits.push_back(fit_around<2>(lane.pts[0], lane.pts, kRadius));
    carried.push_back(lane.carried);
    normals.push_back(lane.carried);
  }
  std::vector<FitStatus> status(lanes.size());
  PrattFit<2>::solve_lanes<PrattFit<2>::kPairs>(fits, carried, normals, status);
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    CAPTURE(k);
    PrattFit<2> alone = fit_around<2>(lanes[k].pts[0], lanes[k].pts, kRadius);
    Vec<2> normal = lanes[k].carried;
    CHECK(status[k] == lanes[k].expected);
    REQUIRE(alone.solve(lanes[k].carried, normal) == status[k]);
    CHECK(normal == normals[k]);
    if (status[k] != FitStatus::ok) continue;
    CHECK(alone.coefficients() == fits[k].coefficients());
    CHECK((normals[k] - reference_normal<2>(lanes[k].pts[0], lanes[k].pts, kRadius, lanes[k].carried)).norm() < 1e-9);
  }
}

}  // namespace

TEST_CASE("Pratt fit reproduces a circle exactly: the pseudo-normal is radial") {
  const Vec<2> center(0.5, 0.75);
  const double r = 0.15;
  std::vector<Vec<2>> pts;
  for (int i = 0; i < 200; ++i) {
    const double a = 2.0 * M_PI * i / 200.0;
    pts.push_back(center + r * Vec<2>(std::cos(a), std::sin(a)));
  }
  for (int i : {0, 17, 99}) {
    auto fit = fit_around<2>(pts[i], pts, 0.03);
    Vec<2> n;
    const Vec<2> radial = (pts[i] - center) / r;
    REQUIRE(fit.solve(radial, n) == FitStatus::ok);
    CHECK((n - radial).norm() < 1e-9);
    // The fitted algebraic circle is the circle: its centre in scaled coordinates.
    const auto& a = fit.coefficients();
    const double a2 = a[3];
    const Vec<2> c = -a.segment<2>(1) / (2.0 * a2) * 0.03 + pts[i];
    CHECK((c - center).norm() < 1e-9);
  }
}

TEST_CASE("Pratt fit reproduces a sphere exactly") {
  const Vec<3> center(0.35, 0.35, 0.35);
  const double r = 0.15;
  std::vector<Vec<3>> pts;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double s = std::sqrt(1 - z * z), phi = i * 2.399963229728653;
    pts.push_back(center + r * Vec<3>(s * std::cos(phi), s * std::sin(phi), z));
  }
  for (int i : {3, 1000, 2500}) {
    auto fit = fit_around<3>(pts[i], pts, 0.03);
    Vec<3> normal;
    const Vec<3> radial = (pts[i] - center) / r;
    REQUIRE(fit.solve(radial, normal) == FitStatus::ok);
    CHECK((normal - radial).norm() < 1e-9);
  }
}

TEST_CASE("Pratt fit orients the normal to agree with the carried one") {
  std::vector<Vec<2>> line;
  for (int i = -5; i <= 5; ++i) line.push_back(Vec<2>(0.01 * i, 0.0));
  auto fit = fit_around<2>(line[5], line, 0.06);
  Vec<2> n;
  REQUIRE(fit.solve(Vec<2>(0.2, -1.0).normalized(), n) == FitStatus::ok);
  CHECK(n.y() == doctest::Approx(-1.0).epsilon(1e-12));
  REQUIRE(fit.solve(Vec<2>(0.3, 1.0).normalized(), n) == FitStatus::ok);
  CHECK(n.y() == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("Pratt fit recovers the normal of a noisy plane") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05), noise(-1e-4, 1e-4);
  std::vector<Vec<3>> pts{Vec<3>::Zero()};
  for (int i = 0; i < 300; ++i) pts.push_back(Vec<3>(u(rng), u(rng), noise(rng)));
  auto fit = fit_around<3>(pts[0], pts, 0.05);
  Vec<3> n;
  REQUIRE(fit.solve(Vec<3>(0, 0, 1), n) == FitStatus::ok);
  CHECK(n.z() > 0.999);
}

TEST_CASE("Pratt fit reports degenerate neighbourhoods and keeps the carried normal") {
  const Vec<3> carried(0, 0, 1);
  SUBCASE("too few points") {
    auto fit = fit_around<3>(Vec<3>::Zero(), {Vec<3>::Zero(), Vec<3>(0.01, 0, 0), Vec<3>(0, 0.01, 0)}, 0.05);
    Vec<3> n = carried;
    CHECK(fit.solve(carried, n) == FitStatus::too_few_neighbours);
    CHECK(n == carried);
  }
  SUBCASE("collinear points in 3D") {
    std::vector<Vec<3>> pts;
    for (int i = -4; i <= 4; ++i) pts.push_back(Vec<3>(0.01 * i, 0.005 * i, 0.0));
    auto fit = fit_around<3>(pts[4], pts, 0.06);
    Vec<3> n = carried;
    CHECK(fit.solve(carried, n) == FitStatus::degenerate);
    CHECK(n == carried);
  }
  SUBCASE("coincident points in 2D") {
    auto fit = fit_around<2>(Vec<2>::Zero(), std::vector<Vec<2>>(5, Vec<2>::Zero()), 0.05);
    Vec<2> n(1, 0);
    CHECK(fit.solve(Vec<2>(1, 0), n) == FitStatus::degenerate);
  }
}

TEST_CASE("Pratt fits solved side by side get what each gets alone") {
  const Vec<2> radial(1.0, 0.0);
  const Vec<2> tilted = Vec<2>(1.0, 0.8).normalized();
  // Exact and noisy arcs, from the radial normal and from far off it: they
  // settle after 2, 3 and 5 iterations, and each lane must stop at its own.
  // Inverse iteration does not settle the noisiest one, which goes to the
  // eigensolver.
  const Lane exact{noisy_arc(0.15, 0.3, 0.0, 1), radial};
  const Lane slightly_noisy{noisy_arc(0.15, 0.3, 1e-4, 2), tilted};
  const Lane noisy{noisy_arc(0.08, 0.6, 5e-3, 3), tilted};
  const Lane straight{noisy_arc(1e3, 1e-4, 1e-3, 4), radial};
  // Fits that fail before any iteration, next to good ones.
  const Lane coincident{std::vector<Vec<2>>(5, Vec<2>::Zero()), radial, FitStatus::degenerate};
  const Lane too_few{{Vec<2>::Zero(), Vec<2>(0.01, 0.0)}, radial, FitStatus::too_few_neighbours};
  check_batch_against_alone({exact, slightly_noisy, noisy, straight});
  check_batch_against_alone({noisy, coincident, exact, too_few});
  check_batch_against_alone({too_few, straight, slightly_noisy});
  check_batch_against_alone({coincident});
}
