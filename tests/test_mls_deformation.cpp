#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/deform/mls_deformation.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

constexpr MlsKind kKinds[] = {MlsKind::affine, MlsKind::similarity, MlsKind::rigid};

template <int D>
Vec<D> random_vec(std::mt19937& rng, double extent = 1.0) {
  std::uniform_real_distribution<double> u(-extent, extent);
  Vec<D> x;
  for (int k = 0; k < D; ++k) x(k) = u(rng);
  return x;
}

template <int D>
std::vector<Vec<D>> random_points(std::mt19937& rng, int count, double extent = 1.0) {
  std::vector<Vec<D>> points;
  for (int i = 0; i < count; ++i) points.push_back(random_vec<D>(rng, extent));
  return points;
}

template <int D>
Mat<D> random_rotation(std::mt19937& rng) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(std::uniform_real_distribution<double>(-M_PI, M_PI)(rng)).toRotationMatrix();
  } else {
    const Eigen::Vector4d c = random_vec<4>(rng);
    return Eigen::Quaterniond(c(0), c(1), c(2), c(3)).normalized().toRotationMatrix();
  }
}

// x -> linear x + shift, the global maps each kind must reproduce.
template <int D>
struct GlobalMap {
  Mat<D> linear;
  Vec<D> shift;
  Vec<D> operator()(const Vec<D>& x) const { return linear * x + shift; }
  std::vector<Vec<D>> operator()(const std::vector<Vec<D>>& xs) const {
    std::vector<Vec<D>> out;
    for (const Vec<D>& x : xs) out.push_back((*this)(x));
    return out;
  }
};

// A random map of the given class: rigid (rotation + translation), similarity
// (times a scale) or affine (any invertible matrix, reflections included).
template <int D>
GlobalMap<D> random_map(std::mt19937& rng, MlsKind kind) {
  GlobalMap<D> g{random_rotation<D>(rng), random_vec<D>(rng, 2.0)};
  if (kind == MlsKind::similarity) g.linear *= std::uniform_real_distribution<double>(0.3, 3.0)(rng);
  if (kind == MlsKind::affine)
    for (int k = 0; k < D; ++k) g.linear.col(k) = Vec<D>::Unit(k) + random_vec<D>(rng, 0.8);
  return g;
}

// The linear part of a rigid map: a rotation, never a reflection.
template <int D>
void check_rotation(const Mat<D>& linear) {
  CHECK(linear.determinant() == doctest::Approx(1.0).epsilon(1e-9));
  CHECK((linear.transpose() * linear - Mat<D>::Identity()).norm() < 1e-9);
}

// Every point of `points` close to a unit normal and on the outside of `center`.
template <int D>
void check_outward_unit_normals(const PointSet<D>& points) {
  Vec<D> centroid = Vec<D>::Zero();
  for (const Vec<D>& p : points.positions) centroid += p / static_cast<double>(points.size());
  int inward = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    CHECK(points.normals[i].norm() == doctest::Approx(1.0).epsilon(1e-12));
    if (points.normals[i].dot(points.positions[i] - centroid) <= 0.0) ++inward;
  }
  CHECK(inward == 0);
}

template <int D>
void check_interpolates_handles() {
  std::mt19937 rng(11 + D);
  const auto from = random_points<D>(rng, 6), to = random_points<D>(rng, 6);
  for (MlsKind kind : kKinds) {
    for (double alpha : {0.5, 1.0, 2.0}) {
      CAPTURE(D);
      CAPTURE(to_string(kind));
      CAPTURE(alpha);
      const MlsDeformation<D> mls(from, to, kind, alpha);
      for (std::size_t i = 0; i < from.size(); ++i) {
        const Vec<D> direction = random_vec<D>(rng).normalized();
        CHECK(mls.map(from[i]) == to[i]);
        // Within rounding distance of a handle is on it.
        CHECK(mls.map(from[i] + 1e-14 * direction) == to[i]);
        // Just outside, f is continuous.
        CHECK((mls.map(from[i] + 1e-7 * direction) - to[i]).norm() < 1e-5);
      }
    }
  }
}

template <int D>
void check_identity_for_still_handles() {
  std::mt19937 rng(21 + D);
  const auto handles = random_points<D>(rng, 7);
  for (MlsKind kind : kKinds) {
    CAPTURE(D);
    CAPTURE(to_string(kind));
    const MlsDeformation<D> mls(handles, handles, kind);
    for (const Vec<D>& x : random_points<D>(rng, 50, 1.5)) {
      const MlsLocalMap<D> local = mls.local_map(x);
      CHECK((local.position - x).norm() < 1e-12);
      CHECK((local.linear - Mat<D>::Identity()).norm() < 1e-12);
    }
  }
}

// Kinds are ordered from the widest class to the narrowest, so a kind must
// reproduce the maps of its own class and of every later one.
template <int D>
void check_reproduces_global_maps() {
  std::mt19937 rng(31 + D);
  for (MlsKind kind : kKinds) {
    for (MlsKind map_class : kKinds) {
      if (map_class < kind) continue;
      for (int trial = 0; trial < 5; ++trial) {
        CAPTURE(D);
        CAPTURE(to_string(kind));
        CAPTURE(to_string(map_class));
        const auto from = random_points<D>(rng, D + 3);
        const GlobalMap<D> g = random_map<D>(rng, map_class);
        const MlsDeformation<D> mls(from, g(from), kind, trial % 2 == 0 ? 1.0 : 1.5);
        for (const Vec<D>& x : random_points<D>(rng, 40, 1.5)) {
          const MlsLocalMap<D> local = mls.local_map(x);
          CHECK((local.position - g(x)).norm() < 1e-9);
          CHECK((local.linear - g.linear).norm() < 1e-9);
        }
        CHECK(mls.fallbacks() == 0);
      }
    }
  }
}

// Rigid and similarity fits at random points stay proper: rotations (times a positive scale).
template <int D>
void check_no_reflection(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, std::mt19937& rng) {
  const MlsDeformation<D> rigid(from, to, MlsKind::rigid), similarity(from, to, MlsKind::similarity);
  for (std::size_t i = 0; i < from.size(); ++i) CHECK(rigid.map(from[i]) == to[i]);
  for (const Vec<D>& x : random_points<D>(rng, 40, 1.5)) {
    const MlsLocalMap<D> local = rigid.local_map(x);
    CHECK(local.position.allFinite());
    check_rotation<D>(local.linear);
    CHECK(similarity.local_map(x).linear.determinant() >= 0.0);
  }
}

template <int D>
GlobalMap<D> mirror_x() {
  Mat<D> m = Mat<D>::Identity();
  m(0, 0) = -1.0;
  return {m, Vec<D>::Zero()};
}

template <int D>
void check_single_handle_translates() {
  std::mt19937 rng(41 + D);
  const Vec<D> p = random_vec<D>(rng), q = random_vec<D>(rng);
  for (MlsKind kind : kKinds) {
    CAPTURE(D);
    CAPTURE(to_string(kind));
    const MlsDeformation<D> mls({p}, {q}, kind);
    CHECK(mls.map(p) == q);
    PointSet<D> points;
    for (const Vec<D>& x : random_points<D>(rng, 30, 2.0)) points.add(x, random_vec<D>(rng).normalized());
    const PointSet<D> before = points;
    ThreadPool pool(1);
    mls.apply(points, pool);
    for (std::size_t i = 0; i < points.size(); ++i) {
      CHECK((points.positions[i] - (before.positions[i] + q - p)).norm() < 1e-12);
      CHECK((points.normals[i] - before.normals[i]).norm() < 1e-12);
    }
    // One handle leaves the affine fit undetermined: it is reported, point by
    // point, except on the handle itself, where nothing is fitted.
    CHECK(mls.fallbacks() == (kind == MlsKind::affine ? points.size() : 0u));
  }
}

template <int D>
void check_no_handles_is_identity() {
  std::mt19937 rng(51 + D);
  for (MlsKind kind : kKinds) {
    const MlsDeformation<D> mls({}, {}, kind);
    PointSet<D> points;
    for (const Vec<D>& x : random_points<D>(rng, 20)) points.add(x, random_vec<D>(rng).normalized());
    const PointSet<D> before = points;
    ThreadPool pool(2);
    mls.apply(points, pool);
    mls.deform(points, 0.2, 0.9, pool);
    CHECK(points.positions == before.positions);
    CHECK(points.normals == before.normals);
    CHECK(mls.fallbacks() == 0);
  }
}

template <int D>
PointSet<D> random_oriented_points(std::mt19937& rng, int count) {
  PointSet<D> points;
  for (const Vec<D>& x : random_points<D>(rng, count, 1.5)) points.add(x, random_vec<D>(rng).normalized());
  return points;
}

template <int D>
void check_thread_count_independence() {
  std::mt19937 rng(61 + D);
  const PointSet<D> points = random_oriented_points<D>(rng, 1000);
  const auto from = random_points<D>(rng, 9), to = random_points<D>(rng, 9);
  for (MlsKind kind : kKinds) {
    CAPTURE(to_string(kind));
    const MlsDeformation<D> mls(from, to, kind);
    PointSet<D> reference = points;
    ThreadPool serial(1);
    mls.apply(reference, serial);
    mls.deform(reference, 0.25, 0.75, serial);
    for (int threads : {2, 3, 8}) {
      PointSet<D> parallel = points;
      ThreadPool pool(threads);
      mls.apply(parallel, pool);
      mls.deform(parallel, 0.25, 0.75, pool);
      CHECK(parallel.positions == reference.positions);
      CHECK(parallel.normals == reference.normals);
    }
  }
}

template <int D>
void check_handle_path() {
  std::mt19937 rng(71 + D);
  const auto from = random_points<D>(rng, 5), to = random_points<D>(rng, 5);
  const MlsDeformation<D> mls(from, to, MlsKind::similarity);
  ThreadPool pool(2);
  const PointSet<D> points = random_oriented_points<D>(rng, 200);

  PointSet<D> applied = points, deformed = points;
  mls.apply(applied, pool);
  mls.deform(deformed, 0.0, 1.0, pool);
  CHECK(deformed.positions == applied.positions);
  CHECK(deformed.normals == applied.normals);

  PointSet<D> still = points;
  mls.deform(still, 0.4, 0.4, pool);
  CHECK(still.positions == points.positions);

  // Points on the handles at t0 land on the handles at t1, in either direction of time.
  for (auto [t0, t1] : {std::pair{0.25, 0.75}, std::pair{0.9, 0.1}}) {
    PointSet<D> on_handles;
    for (const Vec<D>& h : mls.handles_at(t0)) on_handles.add(h, Vec<D>::UnitX());
    mls.deform(on_handles, t0, t1, pool);
    CHECK(on_handles.positions == mls.handles_at(t1));
  }
  CHECK((mls.handles_at(0.5)[3] - 0.5 * (from[3] + to[3])).norm() < 1e-15);
}

template <int D>
void check_robust_near_handles() {
  std::mt19937 rng(81 + D);
  const auto from = random_points<D>(rng, 6), to = random_points<D>(rng, 6);
  for (MlsKind kind : kKinds) {
    for (double alpha : {1.0, 4.0}) {
      CAPTURE(to_string(kind));
      CAPTURE(alpha);
      const MlsDeformation<D> mls(from, to, kind, alpha);
      const Vec<D> direction = random_vec<D>(rng).normalized();
      const MlsLocalMap<D> at_handle = mls.local_map(from[2]);
      CHECK(at_handle.linear.allFinite());
      for (double distance : {1e-300, 1e-200, 1e-20, 1e-13, 1e-11, 1e-8, 1e-6}) {
        CAPTURE(distance);
        const MlsLocalMap<D> local = mls.local_map(from[2] + distance * direction);
        CHECK(local.position.allFinite());
        CHECK((local.position - to[2]).norm() <= 100.0 * distance);
        // The map at a handle is the limit of the maps next to it.
        CHECK((local.linear - at_handle.linear).norm() < 1e-4);
      }
    }
  }
}

// Schaefer et al.'s 2D closed forms as printed, with row vectors:
// A_i = w_i [p^_i; -p^_i⊥] [v - p*; -(v - p*)⊥]^T, similarity f_s = sum q^_i A_i / mu_s + q*,
// rigid f_r = |v - p*| f_vec / |f_vec| + q* with f_vec = sum q^_i A_i, and
// affine f_a = (v - p*) (sum w_i p^_i^T p^_i)^{-1} sum w_j p^_j^T q^_j + q*.
Vec<2> perp(const Vec<2>& a) { return Vec<2>(-a.y(), a.x()); }

Vec<2> paper_closed_form(const std::vector<Vec<2>>& p, const std::vector<Vec<2>>& q, const Vec<2>& v, MlsKind kind) {
  std::vector<double> w;
  double total = 0.0;
  Eigen::RowVector2d p_star = Eigen::RowVector2d::Zero(), q_star = Eigen::RowVector2d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    w.push_back(1.0 / (p[i] - v).squaredNorm());
    total += w[i];
    p_star += w[i] * p[i].transpose();
    q_star += w[i] * q[i].transpose();
  }
  p_star /= total;
  q_star /= total;
  const Eigen::RowVector2d v_hat = v.transpose() - p_star;
  Mat<2> right;
  right << v_hat, -perp(v_hat.transpose()).transpose();
  double mu_s = 0.0;
  Mat<2> moments = Mat<2>::Zero(), cross = Mat<2>::Zero();
  Eigen::RowVector2d sum = Eigen::RowVector2d::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::RowVector2d p_hat = p[i].transpose() - p_star, q_hat = q[i].transpose() - q_star;
    Mat<2> left;
    left << p_hat, -perp(p_hat.transpose()).transpose();
    sum += q_hat * (w[i] * left * right.transpose());
    mu_s += w[i] * p_hat.squaredNorm();
    moments += w[i] * p_hat.transpose() * p_hat;
    cross += w[i] * p_hat.transpose() * q_hat;
  }
  if (kind == MlsKind::affine) return (v_hat * moments.inverse() * cross + q_star).transpose();
  if (kind == MlsKind::similarity) return (sum / mu_s + q_star).transpose();
  return (v_hat.norm() * sum / sum.norm() + q_star).transpose();
}

}  // namespace

TEST_CASE("MLS deformation interpolates its handles exactly, every kind, 2D and 3D") {
  check_interpolates_handles<2>();
  check_interpolates_handles<3>();
}

TEST_CASE("MLS deformation is the identity when the handles do not move") {
  check_identity_for_still_handles<2>();
  check_identity_for_still_handles<3>();
}

TEST_CASE("affine reproduces global affine maps, similarity similarities, rigid rotations plus translations") {
  check_reproduces_global_maps<2>();
  check_reproduces_global_maps<3>();
}

TEST_CASE("2D MLS equals the closed forms of Schaefer et al.") {
  std::mt19937 rng(5);
  const auto from = random_points<2>(rng, 6), to = random_points<2>(rng, 6);
  for (MlsKind kind : kKinds) {
    CAPTURE(to_string(kind));
    const MlsDeformation<2> mls(from, to, kind);
    for (const Vec<2>& v : random_points<2>(rng, 50, 1.5))
      CHECK((mls.map(v) - paper_closed_form(from, to, v, kind)).norm() < 1e-12);
  }
}

TEST_CASE("the rigid variant never reflects, even with coplanar or collinear handles") {
  std::mt19937 rng(9);
  SUBCASE("general handles with random and mirrored targets") {
    const auto from2 = random_points<2>(rng, 6);
    const auto from3 = random_points<3>(rng, 6);
    check_no_reflection<2>(from2, random_points<2>(rng, 6), rng);
    check_no_reflection<2>(from2, mirror_x<2>()(from2), rng);
    check_no_reflection<3>(from3, random_points<3>(rng, 6), rng);
    check_no_reflection<3>(from3, mirror_x<3>()(from3), rng);
  }
  SUBCASE("coplanar handles in 3D") {
    std::vector<Vec<3>> plane;
    for (const Vec<2>& x : random_points<2>(rng, 6)) plane.push_back(Vec<3>(x.x(), x.y(), 0.0));
    check_no_reflection<3>(plane, random_points<3>(rng, 6), rng);
    const GlobalMap<3> tilt{random_rotation<3>(rng), random_vec<3>(rng)};
    check_no_reflection<3>(tilt(plane), random_map<3>(rng, MlsKind::rigid)(plane), rng);
    // Mirrored within their plane, the handles are matched exactly by a half
    // turn about y, which must then move the whole space: (x, y, z) -> (-x, y, -z).
    check_no_reflection<3>(plane, mirror_x<3>()(plane), rng);
    const MlsDeformation<3> rigid(plane, mirror_x<3>()(plane), MlsKind::rigid);
    for (const Vec<3>& x : random_points<3>(rng, 20))
      CHECK((rigid.map(x) - Vec<3>(-x.x(), x.y(), -x.z())).norm() < 1e-9);
  }
  SUBCASE("collinear handles in 2D") {
    std::vector<Vec<2>> line;
    for (double s : {-0.9, -0.3, 0.1, 0.4, 0.8}) line.push_back(Vec<2>(s, 0.5 * s + 0.1));
    check_no_reflection<2>(line, random_points<2>(rng, 5), rng);
    check_no_reflection<2>(line, mirror_x<2>()(line), rng);
    // In 2D a line of handles still fixes the rotation: rigid maps are reproduced.
    const GlobalMap<2> g = random_map<2>(rng, MlsKind::rigid);
    const MlsDeformation<2> rigid(line, g(line), MlsKind::rigid);
    for (const Vec<2>& x : random_points<2>(rng, 20)) CHECK((rigid.map(x) - g(x)).norm() < 1e-9);
  }
  SUBCASE("collinear handles in 3D") {
    const Vec<3> direction = random_vec<3>(rng).normalized(), origin = random_vec<3>(rng, 0.2);
    std::vector<Vec<3>> line;
    for (double s : {-0.9, -0.3, 0.1, 0.4, 0.8}) line.push_back(origin + s * direction);
    check_no_reflection<3>(line, random_points<3>(rng, 5), rng);
    check_no_reflection<3>(line, random_map<3>(rng, MlsKind::rigid)(line), rng);
    // Reversed along their line: the opposite-directions branch, a half turn.
    const GlobalMap<3> reverse{-Mat<3>::Identity(), 2.0 * origin};
    check_no_reflection<3>(line, reverse(line), rng);
    // A line of handles does not fix a spin about itself; the fit adds none,
    // so a translated line translates everything.
    const Vec<3> shift = random_vec<3>(rng);
    const MlsDeformation<3> rigid(line, GlobalMap<3>{Mat<3>::Identity(), shift}(line), MlsKind::rigid);
    for (const Vec<3>& x : random_points<3>(rng, 20)) CHECK((rigid.map(x) - (x + shift)).norm() < 1e-9);
  }
}

TEST_CASE("affine falls back to similarity where its moment matrix is singular, and reports it") {
  std::mt19937 rng(13);
  ThreadPool pool(2);
  SUBCASE("coplanar handles in 3D") {
    const GlobalMap<3> tilt{random_rotation<3>(rng), random_vec<3>(rng)};
    std::vector<Vec<3>> plane;
    for (const Vec<2>& x : random_points<2>(rng, 7)) plane.push_back(tilt(Vec<3>(x.x(), x.y(), 0.0)));
    const auto to = random_points<3>(rng, 7);
    const MlsDeformation<3> affine(plane, to, MlsKind::affine), similarity(plane, to, MlsKind::similarity);
    const auto probes = random_points<3>(rng, 30, 1.5);
    for (const Vec<3>& x : probes) {
      const MlsLocalMap<3> local = affine.local_map(x);
      CHECK(local.affine_fell_back);
      CHECK(local.position.allFinite());
      CHECK((local.position - similarity.map(x)).norm() < 1e-12);
    }
    CHECK(affine.fallbacks() == probes.size());
    CHECK(similarity.fallbacks() == 0);
    PointSet<3> points = random_oriented_points<3>(rng, 100);
    affine.apply(points, pool);
    CHECK(affine.fallbacks() == probes.size() + 100);
    for (std::size_t i = 0; i < points.size(); ++i) {
      CHECK(points.positions[i].allFinite());
      CHECK(points.normals[i].norm() == doctest::Approx(1.0).epsilon(1e-12));
    }
    affine.reset_fallbacks();
    CHECK(affine.fallbacks() == 0);
  }
  SUBCASE("collinear handles in 2D") {
    std::vector<Vec<2>> line;
    for (double s : {-0.7, 0.0, 0.2, 0.9}) line.push_back(Vec<2>(0.3 * s, s));
    const MlsDeformation<2> affine(line, random_points<2>(rng, 4), MlsKind::affine);
    CHECK(affine.local_map(Vec<2>(0.5, 0.1)).affine_fell_back);
    CHECK(affine.map(Vec<2>(0.5, 0.1)).allFinite());
    CHECK(affine.fallbacks() == 2);
  }
  SUBCASE("handles in general position never fall back") {
    const MlsDeformation<3> affine(random_points<3>(rng, 8), random_points<3>(rng, 8), MlsKind::affine);
    PointSet<3> points = random_oriented_points<3>(rng, 100);
    affine.apply(points, pool);
    CHECK(affine.fallbacks() == 0);
  }
}

TEST_CASE("carried normals stay unit length and point outward under a smooth handle deformation") {
  std::mt19937 rng(17);
  ThreadPool pool(2);
  SUBCASE("circle") {
    const Vec<2> center(0.3, -0.2);
    std::vector<Vec<2>> from;
    for (int i = 0; i < 8; ++i) from.push_back(center + 1.25 * Vec<2>(std::cos(i * M_PI / 4), std::sin(i * M_PI / 4)));
    const GlobalMap<2> stretch{Vec<2>(1.3, 0.8).asDiagonal(), Vec<2>(0.1, 0.0)};
    std::vector<Vec<2>> to = stretch(from);
    for (Vec<2>& q : to) q += random_vec<2>(rng, 0.08);
    for (MlsKind kind : kKinds) {
      CAPTURE(to_string(kind));
      PointSet<2> points = sample_circle(center, 1.0, 256);
      MlsDeformation<2>(from, to, kind).apply(points, pool);
      check_outward_unit_normals(points);
    }
  }
  SUBCASE("a mirror, where the affine map reverses orientation") {
    // L^{-T} keeps each normal on the side the outside went to, though det L < 0.
    std::vector<Vec<2>> from;
    for (int i = 0; i < 5; ++i) from.push_back(1.5 * Vec<2>(std::cos(i * 1.3), std::sin(i * 1.7)));
    PointSet<2> points = sample_circle(Vec<2>(0.2, 0.1), 1.0, 128);
    MlsDeformation<2>(from, mirror_x<2>()(from), MlsKind::affine).apply(points, pool);
    check_outward_unit_normals(points);
  }
  SUBCASE("sphere") {
    const Vec<3> center(0.1, 0.2, -0.1);
    std::vector<Vec<3>> from;
    for (int i = 0; i < 8; ++i) from.push_back(center + 1.2 * Vec<3>(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    const GlobalMap<3> stretch{
        Eigen::AngleAxisd(0.3, Vec<3>(1, 2, 3).normalized()).toRotationMatrix() * Vec<3>(1.2, 0.9, 1.1).asDiagonal(),
        Vec<3>::Zero()};
    std::vector<Vec<3>> to = stretch(from);
    for (Vec<3>& q : to) q += random_vec<3>(rng, 0.05);
    for (MlsKind kind : kKinds) {
      CAPTURE(to_string(kind));
      const PointSet<3> sphere = sample_sphere(center, 1.0, 2000);
      PointSet<3> points = sphere;
      const MlsDeformation<3> mls(from, to, kind);
      mls.apply(points, pool);
      check_outward_unit_normals(points);
      // Rigid normals are the local rotation applied to the old ones.
      if (kind == MlsKind::rigid)
        for (std::size_t i = 0; i < points.size(); i += 97)
          CHECK((points.normals[i] - mls.local_map(sphere.positions[i]).linear * sphere.normals[i]).norm() < 1e-12);
    }
  }
}

TEST_CASE("a single handle translates everything - no handles leave everything in place") {
  check_single_handle_translates<2>();
  check_single_handle_translates<3>();
  check_no_handles_is_identity<2>();
  check_no_handles_is_identity<3>();
}

TEST_CASE("MLS deformation gives the same points and normals for any thread count") {
  check_thread_count_independence<2>();
  check_thread_count_independence<3>();
}

TEST_CASE("deform(t0, t1) maps the handles at lerp(t0) onto the handles at lerp(t1)") {
  check_handle_path<2>();
  check_handle_path<3>();
}

TEST_CASE("MLS deformation stays finite and continuous right next to a handle") {
  check_robust_near_handles<2>();
  check_robust_near_handles<3>();
}

TEST_CASE("MLS deformation rejects invalid handles, weights and times") {
  const std::vector<Vec<3>> good{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0)};
  std::vector<Vec<3>> nan_from = good, inf_to = good;
  nan_from[2].y() = std::nan("");
  inf_to[1].z() = INFINITY;
  CHECK_THROWS_WITH_AS(MlsDeformation<3>(good, {good[0], good[1]}), doctest::Contains("3 handle start positions but 2"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(MlsDeformation<3>(nan_from, good), doctest::Contains("handle 2 has a non-finite start"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(MlsDeformation<3>(good, inf_to), doctest::Contains("handle 1 has a non-finite target"),
                       std::invalid_argument);
  for (double alpha : {0.0, -1.0, std::nan(""), double(INFINITY)})
    CHECK_THROWS_WITH_AS(MlsDeformation<3>(good, good, MlsKind::rigid, alpha), doctest::Contains("alpha"),
                         std::invalid_argument);
  const MlsDeformation<3> mls(good, good);
  PointSet<3> points;
  points.add(Vec<3>(0.5, 0.5, 0.5), Vec<3>::UnitZ());
  ThreadPool pool(1);
  CHECK_THROWS_WITH_AS(mls.deform(points, 0.0, 1.5, pool), doctest::Contains("time 1.5"), std::invalid_argument);
  CHECK_THROWS_AS(mls.deform(points, std::nan(""), 1.0, pool), std::invalid_argument);
  points.normals.push_back(Vec<3>::UnitX());
  CHECK_THROWS_WITH_AS(mls.apply(points, pool), doctest::Contains("1 points but 2 normals"), std::invalid_argument);
}

TEST_CASE("MLS kind names: to_string and parse_mls_kind are inverse, and unknown names list the accepted ones") {
  for (MlsKind kind : {MlsKind::affine, MlsKind::similarity, MlsKind::rigid}) CHECK(parse_mls_kind(to_string(kind)) == kind);
  CHECK_THROWS_WITH_AS(parse_mls_kind("Rigid"), "unknown deformation kind 'Rigid' (expected affine, similarity or rigid)",
                       std::invalid_argument);
}
