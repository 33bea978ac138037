#include "core/resample/mesh_extraction.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>

#include "core/geometry/sliver_collapse.hpp"
#include "core/resample/segment_root.hpp"
#include "core/util/flat_hash_map.hpp"

namespace amls {

namespace {

template <int D>
constexpr int kCubeCorners = 1 << D;

// Mesh vertices keep at least this fraction of their edge from its ends.
// Where F vanishes at or next to a grid vertex, the crossings on the edges
// leaving it would otherwise meet there: vertices in one place and triangles
// of no area, which slicers and mesh checkers reject. This moves a vertex by
// at most 1e-3 h, far less than the mesh's chord error (the sphere test's
// facets lie up to about 1e-2 h inside the sphere).
constexpr double kEndMargin = 1e-3;

// Mesh vertices are rounded to multiples of h / 2^12 from the grid's origin,
// moving them by at most 2.2e-4 h (a fifth of the end margin, far below the
// chord error). Where a flat face of the surface is parallel to a grid plane
// (a CAD model's base), its vertices' roots differ in the last bits, so the
// face is flat only to about 1e-17; other programs' triangle tests then
// misjudge nearly coplanar neighbours (Open3D's, with its 1e-6 tolerance on
// the scaled distances, found hundreds of "crossing" pairs on CGAL's
// fandisk_large.off). Rounded, the face's vertices share one exact coordinate,
// and the face is exactly flat. A flat face at an angle to the grid (a
// chamfer, a cube's rounded edge) is flat only to rounding, but where it runs
// through grid vertices, a vertex merged beside one (core/geometry/
// sliver_collapse.hpp), a few units of h / 2^20 off it, rounds onto it: with
// h / 2^20 Open3D still took 12 pairs of triangles on CGAL's cube.off, 3 on
// fandisk_large.off, 7 on couplingdown.off and 5 on spool.off for crossing
// ones, all apart in exact arithmetic; with h / 2^12, none.
constexpr double kVertexLattice = 1.0 / (1 << 12);

// A simplex of Kuhn's triangulation of the unit cube: its corners (as cube
// corners, each one axis beyond the last) and the sign of its orientation,
// det(c1 - c0, ..., cD - c0), which is the sign of its axis permutation.
template <int D>
struct KuhnSimplex {
  std::array<int, D + 1> corners{};
  int sign = 1;
};

template <std::size_t N>
int permutation_sign(const std::array<int, N>& order) {
  int inversions = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j) inversions += static_cast<int>(order[i] > order[j]);
  return inversions % 2 == 0 ? 1 : -1;
}

template <int D>
std::vector<KuhnSimplex<D>> kuhn_simplices() {
  std::array<int, D> axes{};
  std::iota(axes.begin(), axes.end(), 0);
  std::vector<KuhnSimplex<D>> simplices;
  do {
    KuhnSimplex<D> s;
    for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k) s.corners[k + 1] = s.corners[k] | (1 << axes[k]);
    s.sign = permutation_sign(axes);
    simplices.push_back(s);
  } while (std::next_permutation(axes.begin(), axes.end()));
  return simplices;
}

// A simplex's corners in an order of our choosing, with the sign of the
// permutation from the simplex's own order.
template <std::size_t N>
struct Reordered {
  std::array<int, N> at{};  // at[k]: the simplex corner (0..N-1) placed k-th
  int sign = 1;
};

// The corners with the lone one (index `lone`) first and the others after it
// in increasing order.
template <std::size_t N>
Reordered<N> lone_first(int lone) {
  Reordered<N> r;
  r.at[0] = lone;
  std::size_t k = 1;
  for (int c = 0; c < static_cast<int>(N); ++c)
    if (c != lone) r.at[k++] = c;
  r.sign = permutation_sign(r.at);
  return r;
}

template <int D>
class MeshBuilder {
 public:
  MeshBuilder(const AmlsSurface<D>& surface, const Resampler<D>& resampler, const KnownSide<D>& known_side)
      : surface_(surface), resampler_(resampler), simplices_(kuhn_simplices<D>()), known_side_(known_side) {}

  ExtractedMesh<D> build(Variant variant, ThreadPool& pool) {
    const Grid<D>& grid = surface_.grid();
    // The cubes holding a point whose corners change sign, in the points'
    // order; then, breadth first, the cubes across their faces that change sign.
    // A point on a grid plane whose own cube does not change sign (the surface through grid vertices,
    // where F's zero counts as positive: a flat face on a grid plane) may have its sign change in a
    // cube across the plane. Those cubes start only what the walk from the others did not reach, so
    // that where it reached everything the mesh is the same, triangle for triangle.
    std::vector<IVec<D>> across_planes;
    for (const Vec<D>& p : surface_.points().positions) {
      const IVec<D> cube = grid.cell_of(p);
      if (try_start(cube)) continue;
      const Vec<D> at = (p - grid.vertex_position(cube)) / grid.spacing();
      IVec<D> across = IVec<D>::Zero();
      for (int a = 0; a < D; ++a) across[a] = at[a] < kOnPlane ? -1 : at[a] > 1.0 - kOnPlane ? 1 : 0;
      for_each_index_in_box<D>(IVec<D>(across.cwiseMin(0)), IVec<D>(across.cwiseMax(0)), [&](const IVec<D>& step) {
        if (!step.isZero()) across_planes.push_back(IVec<D>(cube + step));
      });
    }
    std::size_t next = 0;
    auto walk = [&] {
      for (; next < queue_.size(); ++next) {
        const IVec<D> cube = queue_[next];
        const Corners corners = corner_values(cube);
        if (!corners.defined) ++out_.stats.undefined_cubes;
        if (!meshable(corners)) continue;
        queue_neighbours(cube, corners.negative);
        for (const KuhnSimplex<D>& simplex : simplices_) mesh_simplex(cube, corners, simplex);
      }
    };
    walk();
    for (const IVec<D>& cube : across_planes) try_start(cube);
    walk();
    locate_vertices(variant, pool);
    // Where F is nearly zero at a grid vertex, the vertices beside it are merged (sliver_collapse.hpp).
    if constexpr (D == 3) out_.stats.collapsed_vertices = collapse_slivers(out_.mesh, grid);
    round_to_lattice(grid);
    return std::move(out_);
  }

 private:
  static constexpr int kCorners = kCubeCorners<D>;
  static constexpr int kAllCorners = (1 << kCorners) - 1;
  static constexpr std::uint8_t kUnseen = 0, kQueued = 1, kNotStart = 2;

  struct Corners {
    std::array<Evaluation<D>, kCubeCorners<D>> values;
    bool defined = true;
    int negative = 0;  // bit c: F < 0 at corner c
  };

  // A mesh vertex: the edge from `from` to `from + corner_offset(direction)`.
  struct Edge {
    IVec<D> from;
    int direction;
  };

  // How near a grid plane, in h, a point counts as on it for the start cubes.
  static constexpr double kOnPlane = 1e-9;

  // Queues `cube` as a start when its corners change sign; false when they do not (or it was seen).
  bool try_start(const IVec<D>& cube) {
    std::uint8_t& state = *cube_state_.try_emplace(Grid<D>::key(cube)).first;
    if (state != kUnseen) return state == kQueued;
    const Corners corners = corner_values(cube);
    const bool start = meshable(corners) && corners.negative != 0 && corners.negative != kAllCorners;
    state = start ? kQueued : kNotStart;
    if (start) queue_.push_back(cube);
    return start;
  }

  // A cube with a corner where F is undefined is meshed only where the
  // caller says which side such a corner lies on.
  bool meshable(const Corners& corners) const { return corners.defined || static_cast<bool>(known_side_); }

  // Whether a corner counts as negative: the caller's side where it knows
  // it (asked once per vertex), else F < 0 there.
  bool negative_at(const IVec<D>& vertex, const Evaluation<D>& e) {
    if (!known_side_) return e.value < 0.0;
    auto [side, inserted] = known_sides_.try_emplace(Grid<D>::key(vertex));
    if (inserted) {
      *side = known_side_(surface_.grid().vertex_position(vertex)) ? 1 : 0;
      if (e.defined && (e.value < 0.0) != (*side != 0)) ++out_.stats.overruled_signs;
    }
    return *side != 0;
  }

  // F at a vertex where value() has been called.
  const Evaluation<D>& known_value(const IVec<D>& vertex) const {
    if (const Evaluation<D>* known = resampler_.vertex_value(vertex)) return *known;
    return extra_values_[*extra_.find(Grid<D>::key(vertex))];
  }

  // F at a vertex: update_function()'s value, else evaluated here once.
  const Evaluation<D>& value(const IVec<D>& vertex) {
    if (const Evaluation<D>* known = resampler_.vertex_value(vertex)) return *known;
    auto [slot, inserted] = extra_.try_emplace(Grid<D>::key(vertex));
    if (inserted) {
      *slot = static_cast<std::uint32_t>(extra_values_.size());
      extra_values_.push_back(surface_.evaluate(surface_.grid().vertex_position(vertex)));
      ++out_.stats.extra_evaluations;
    }
    return extra_values_[*slot];
  }

  Corners corner_values(const IVec<D>& cube) {
    Corners corners;
    for (int c = 0; c < kCubeCorners<D>; ++c) {
      const IVec<D> vertex = cube + corner_offset<D>(c);
      const Evaluation<D>& e = corners.values[static_cast<std::size_t>(c)] = value(vertex);
      corners.defined = corners.defined && e.defined;
      if (negative_at(vertex, e)) corners.negative |= 1 << c;
    }
    return corners;
  }

  // Queues the cubes across the faces whose corners change sign: the surface
  // goes on there.
  void queue_neighbours(const IVec<D>& cube, int negative) {
    for (int axis = 0; axis < D; ++axis)
      for (int side = 0; side < 2; ++side) {
        int face = 0;
        for (int c = 0; c < kCubeCorners<D>; ++c)
          if (((c >> axis) & 1) == side) face |= 1 << c;
        const int face_negative = negative & face;
        if (face_negative == 0 || face_negative == face) continue;
        IVec<D> neighbour = cube;
        neighbour[axis] += side == 0 ? -1 : 1;
        std::uint8_t& state = *cube_state_.try_emplace(Grid<D>::key(neighbour)).first;
        if (state == kQueued) continue;
        state = kQueued;
        queue_.push_back(neighbour);
      }
  }

  // The mesh vertex on the edge between cube corners a and b (a's bits a subset of b's).
  std::uint32_t edge_vertex(const IVec<D>& cube, int a, int b) {
    const IVec<D> from = cube + corner_offset<D>(a);
    const int direction = a ^ b;
    std::uint32_t& id = (*edge_ids_.try_emplace(Grid<D>::key(from)).first)[static_cast<std::size_t>(direction - 1)];
    if (id == 0) {
      edges_.push_back({from, direction});
      id = static_cast<std::uint32_t>(edges_.size());  // ids are stored plus one: 0 is "none yet"
    }
    return id - 1;
  }

  // The mesh vertex on the edge between simplex corners i and j.
  std::uint32_t simplex_edge(const IVec<D>& cube, const KuhnSimplex<D>& simplex, int i, int j) {
    const int a = simplex.corners[static_cast<std::size_t>(std::min(i, j))];
    const int b = simplex.corners[static_cast<std::size_t>(std::max(i, j))];
    return edge_vertex(cube, a, b);
  }

  // The simplex's part of the surface, facing the positive side. With the
  // corners reordered to (a, b, ...) by a permutation of sign s, and the
  // simplex's orientation sign sigma:
  // - 2D, lone corner a negative, b and c positive: the segment (ab, ac) has
  //   a on its left when sigma * s > 0 (for a = (0,0), b = (1,0), c = (0,1),
  //   the segment from (1/2,0) to (0,1/2) has a on its left).
  // - 3D, lone corner a negative: the triangle (ab, ac, ad) faces away from a
  //   when sigma * s > 0 (det(ab - a, ac - a, ad - a) has the sign of det(b -
  //   a, c - a, d - a), scaled by the edge fractions).
  // - 3D, a and b negative, c and d positive: the triangles (ac, ad, bd) and
  //   (ac, bd, bc) face from {a, b} to {c, d} when sigma * s > 0 (checked on
  //   the unit corner simplex, and no placement of their vertices on the open
  //   edges makes them degenerate, so it holds for all).
  // A lone positive corner is the lone negative case turned over.
  void mesh_simplex(const IVec<D>& cube, const Corners& corners, const KuhnSimplex<D>& simplex) {
    constexpr std::size_t n = D + 1;
    std::array<bool, n> negative{};
    int negatives = 0;
    for (std::size_t k = 0; k < n; ++k) {
      negative[k] = (corners.negative >> simplex.corners[k]) & 1;
      negatives += static_cast<int>(negative[k]);
    }
    if (negatives == 0 || negatives == static_cast<int>(n)) return;
    auto edge = [&](int i, int j) { return simplex_edge(cube, simplex, i, j); };
    if (negatives == 1 || negatives == static_cast<int>(n) - 1) {
      const bool lone_negative = negatives == 1;
      int lone = 0;
      while (negative[static_cast<std::size_t>(lone)] != lone_negative) ++lone;
      const Reordered<n> r = lone_first<n>(lone);
      const bool facing = (simplex.sign * r.sign > 0) == lone_negative;
      if constexpr (D == 2) {
        std::array<std::uint32_t, 2> segment{edge(r.at[0], r.at[1]), edge(r.at[0], r.at[2])};
        if (!facing) std::swap(segment[0], segment[1]);
        out_.mesh.cells.push_back(segment);
      } else {
        std::array<std::uint32_t, 3> triangle{edge(r.at[0], r.at[1]), edge(r.at[0], r.at[2]), edge(r.at[0], r.at[3])};
        if (!facing) std::swap(triangle[1], triangle[2]);
        out_.mesh.cells.push_back(triangle);
      }
      return;
    }
    if constexpr (D == 3) {
      // Two and two: (a, b) the negative corners, (c, d) the positive ones, each pair in increasing order.
      Reordered<n> r;
      std::size_t front = 0, back = 2;
      for (int k = 0; k < static_cast<int>(n); ++k) r.at[negative[static_cast<std::size_t>(k)] ? front++ : back++] = k;
      r.sign = permutation_sign(r.at);
      const auto [a, b, c, d] = r.at;
      const std::uint32_t ac = edge(a, c), ad = edge(a, d), bd = edge(b, d), bc = edge(b, c);
      if (simplex.sign * r.sign > 0) {
        out_.mesh.cells.push_back({ac, ad, bd});
        out_.mesh.cells.push_back({ac, bd, bc});
      } else {
        out_.mesh.cells.push_back({ac, bd, ad});
        out_.mesh.cells.push_back({ac, bc, bd});
      }
    }
  }

  // Every edge's vertex and normal, in parallel: each edge writes only its own.
  void locate_vertices(Variant variant, ThreadPool& pool) {
    const Grid<D>& grid = surface_.grid();
    const double h = grid.spacing();
    SurfaceMesh<D>& mesh = out_.mesh;
    mesh.vertices.resize(edges_.size());
    mesh.normals.resize(edges_.size());
    std::vector<OwnCacheLine<std::size_t>> fallbacks(static_cast<std::size_t>(pool.threads()));
    pool.parallel_for(edges_.size(), [&](std::size_t begin, std::size_t end, int block) {
      for (std::size_t k = begin; k < end; ++k) {
        const Edge& e = edges_[k];
        const Evaluation<D>& f0 = known_value(e.from);
        const Evaluation<D>& f1 = known_value(e.from + corner_offset<D>(e.direction));
        const Vec<D> start = grid.vertex_position(e.from);
        const Vec<D> step = h * corner_offset<D>(e.direction).template cast<double>();
        const int axis = std::countr_zero(static_cast<unsigned>(e.direction));
        SegmentRoot<D> root;
        if (known_side_ && overruled(e, f0, f1)) {
          root = overruled_root(e, f0, f1, step, axis);
        } else if (!f0.defined || !f1.defined) {
          root = cap_root(f0.defined ? f0 : f1, f0.defined, step, axis);
        } else if (variant == Variant::interpolated) {
          root = interpolate_segment_root(f0, f1, axis);
        } else {
          const double guess = estimate_segment_root<D>(f0, f1, step);
          root = locate_segment_root<D>([&](const Vec<D>& y) { return surface_.evaluate(y); }, start, step, f0, f1,
                                        guess, axis);
        }
        fallbacks[static_cast<std::size_t>(block)].value += static_cast<std::size_t>(root.fallback);
        mesh.vertices[k] = start + std::clamp(root.t, kEndMargin, 1.0 - kEndMargin) * step;
        mesh.normals[k] = root.normal;
      }
    });
    for (const auto& f : fallbacks) out_.stats.root_fallbacks += f.value;
  }

  // Whether F at a vertex is defined and of the side the caller gives it.
  bool agrees(const IVec<D>& vertex, const Evaluation<D>& f) const {
    return f.defined && (f.value < 0.0) == (*known_sides_.find(Grid<D>::key(vertex)) != 0);
  }

  // Whether the caller's sides overrule F on an edge: unless F is of the
  // sides at both ends, or at one while undefined at the other (cap_root).
  bool overruled(const Edge& e, const Evaluation<D>& f0, const Evaluation<D>& f1) const {
    const bool agree0 = agrees(e.from, f0), agree1 = agrees(e.from + corner_offset<D>(e.direction), f1);
    return !((agree0 && agree1) || (agree0 && !f1.defined) || (agree1 && !f0.defined));
  }

  // The crossing on an edge from a corner where F is defined (`known`, at the
  // edge's start when `from_start`) to one where it is undefined and of the
  // other side (KnownSide): where F's first-order extrapolation from the
  // known end reaches zero, else at the undefined end (kEndMargin keeps it on
  // the edge), with the known end's normal.
  static SegmentRoot<D> cap_root(const Evaluation<D>& known, bool from_start, const Vec<D>& step, int axis) {
    const double reach = -known.value / known.gradient.dot(from_start ? step : Vec<D>(-step));
    const double fraction = reach > 0.0 && reach < 1.0 ? reach : 1.0;  // false for NaN too
    SegmentRoot<D> root;
    root.t = from_start ? fraction : 1.0 - fraction;
    root.normal = oriented_unit_normal<D>(known.gradient, known.mean_normal, axis);
    return root;
  }

  // The crossing on an edge whose ends' sides, as the caller gives them,
  // are not both F's: F's sign jumps there, or F's zero set strays from the
  // input's surface. |F| still measures the distance to the surface, so
  // with both ends defined the crossing is the zero of the interpolant of
  // |F| signed by the sides; with an end undefined, the edge's midpoint.
  SegmentRoot<D> overruled_root(const Edge& e, const Evaluation<D>& f0, const Evaluation<D>& f1, const Vec<D>& step,
                                int axis) const {
    const bool start_negative = *known_sides_.find(Grid<D>::key(e.from)) != 0;
    SegmentRoot<D> root;
    root.t = 0.5;
    if (f0.defined && f1.defined) {
      const double g0 = start_negative ? -std::abs(f0.value) : std::abs(f0.value);
      const double g1 = start_negative ? std::abs(f1.value) : -std::abs(f1.value);
      if (g0 != g1) root.t = g0 / (g0 - g1);
      root.normal = interpolated_normal(f0, f1, root.t, axis);
    } else {
      // Outward: from the negative end to the positive one.
      root.normal = (start_negative ? 1.0 : -1.0) * step.normalized();
    }
    return root;
  }

  void round_to_lattice(const Grid<D>& grid) {
    const double step = kVertexLattice * grid.spacing();
    for (Vec<D>& v : out_.mesh.vertices)
      v = grid.origin() + step * ((v - grid.origin()) / step).array().round().matrix();
  }

  const AmlsSurface<D>& surface_;
  const Resampler<D>& resampler_;
  const std::vector<KuhnSimplex<D>> simplices_;
  const KnownSide<D>& known_side_;
  FlatHashMap<std::uint8_t> known_sides_;  // vertex -> 1 inside, 0 outside, where the caller gives it
  FlatHashMap<std::uint8_t> cube_state_;
  std::vector<IVec<D>> queue_;
  FlatHashMap<std::uint32_t> extra_;  // vertex -> index in extra_values_
  std::vector<Evaluation<D>> extra_values_;
  FlatHashMap<std::array<std::uint32_t, kCubeCorners<D> - 1>> edge_ids_;  // lower vertex -> its edges' ids plus one
  std::vector<Edge> edges_;
  ExtractedMesh<D> out_;
};

}  // namespace

template <int D>
ExtractedMesh<D> extract_mesh(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool,
                              const KnownSide<D>& known_side) {
  Resampler<D> resampler;
  resampler.update_function(surface, pool);
  return MeshBuilder<D>(surface, resampler, known_side).build(variant, pool);
}

template <int D>
ExtractedMesh<D> extract_mesh(const PointSet<D>& points, const Grid<D>& grid, const AmlsParameters& parameters,
                              Variant variant, ThreadPool& pool, const KnownSide<D>& known_side) {
  AmlsSurface<D> surface(grid, parameters);
  surface.set_points(points);
  surface.hash_points(pool);
  surface.update_normals(pool);
  return extract_mesh(surface, variant, pool, known_side);
}

template ExtractedMesh<2> extract_mesh<2>(const AmlsSurface<2>&, Variant, ThreadPool&, const KnownSide<2>&);
template ExtractedMesh<3> extract_mesh<3>(const AmlsSurface<3>&, Variant, ThreadPool&, const KnownSide<3>&);
template ExtractedMesh<2> extract_mesh<2>(const PointSet<2>&, const Grid<2>&, const AmlsParameters&, Variant,
                                          ThreadPool&, const KnownSide<2>&);
template ExtractedMesh<3> extract_mesh<3>(const PointSet<3>&, const Grid<3>&, const AmlsParameters&, Variant,
                                          ThreadPool&, const KnownSide<3>&);

}  // namespace amls
