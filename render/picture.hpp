#pragma once
// What `amls render` draws, without GL: an input file turned into the renderer's
// content, and the view it is seen from.
//
// Inputs, told apart by their extension and header:
// - a scene (.json, docs/scene-format.md): its state after K steps (core/run/scene_state.hpp),
//   drawn with its handles; h is the scene's grid spacing;
// - a triangle mesh (.obj, or .ply with faces): sampled at h with face normals;
// - a point set (.ply, .xyz, 2D or 3D): as read, with normals estimated (Pratt fit
//   over Delta) where the file has none.
// For files, h is given or estimated (see PictureInputOptions::spacing).
// A 2D picture also shows the MLS curve, the zero set of F of the points' AMLS
// surface (grid h, Delta = radius_factor h), traced by marching squares.
//
// Views: a 3D picture is seen in perspective, by default from azimuth 30 and
// elevation 20 degrees (the eye on +z turned 30 degrees towards +x and raised 20
// degrees towards +y; see render/camera.hpp), centred and framed to fit. A 2D
// picture is seen orthographically (x right, y up), centred and framed to fit.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/run/scene_run.hpp"
#include "core/util/parameter_ranges.hpp"
#include "render/headless.hpp"
#include "render/splat_renderer.hpp"

namespace amls {

// PictureInputOptions::step for a scene's state after its whole history.
constexpr std::size_t kFinalStep = std::numeric_limits<std::size_t>::max();

struct PictureInputOptions {
  // Scenes only: the state after this many steps (kFinalStep: after all of them); none: 0.
  std::optional<std::size_t> step;
  // Point sets and meshes only: h, the sampling spacing (splat size, normal length and
  // quality are in its units; a mesh is sampled at it). 0: a point set's median
  // nearest-neighbour distance, a mesh's bounding-box diagonal / 200.
  double spacing = 0.0;
  double radius_factor = 3.0;  // Delta = radius_factor h: the MLS curve (2D), normal estimation
  int dimension = 0;           // point sets only: 0 decides from the file, 2 or 3 forces it
  int threads = 1;
  bool curve = true;       // 2D: trace the MLS curve
  bool quality = false;    // compute each point's nearest-neighbour spacing in units of h
  SceneProgress progress;  // scenes: called after every step of the run
};

struct Picture {
  int dimension = 3;
  PointSet<3> points;                 // a 2D set has z = 0 and nz = 0
  double h = 0.0;                     // the sampling spacing
  std::vector<glm::vec2> curve;       // 2D: the MLS curve, segment endpoints in pairs
  std::vector<glm::vec3> handles;     // scenes: the handles at the state drawn
  std::vector<double> quality;        // if asked: per point, nearest-neighbour spacing / h
  std::string description;            // what was read and made, one line
  std::vector<std::string> warnings;  // each names the file

  // Puts the picture into the renderer (points with spacing h, quality as scalars, curve, handles).
  void fill(SplatRenderer& renderer) const;
};

// Reads `path` as above. Throws std::runtime_error naming the file for one that cannot
// be read, holds no points, or has a point with a non-finite position or normal or a
// zero normal; std::invalid_argument for options that do not fit the input (a step
// for a file, a spacing or dimension for a scene, a step past the scene's end).
Picture load_picture(const std::string& path, const PictureInputOptions& options);

// --view az,el[,dist]: degrees, degrees, and the eye's distance from the centre
// in world units (none: framed to fit).
struct OrbitView {
  float azimuth_deg = 30.0f;
  float elevation_deg = 20.0f;
  std::optional<float> distance;
};

// "az,el" or "az,el,dist". Throws std::invalid_argument saying what is wrong:
// not 2 or 3 numbers, a non-finite number, an elevation outside [-89.9, 89.9], a distance not above 0.
OrbitView parse_view(const std::string& text);

// The job for a picture: its size, the camera (see the header comment; `view` is
// for 3D pictures only, and throws std::invalid_argument for a 2D one) and options.
// Framing to fit uses the box around everything drawn (points with their splats and
// normals, curve, handles) as seen from the camera, so that elongated shapes fill the
// image; the centre is that box's centre. In 2D, dots are sized to about half the
// spacing on screen (1.5 to 7 px) in a colour apart from the curve's. For
// ColorMode::scalar (quality) the colour range is fixed at 0.3 h .. 1.5 h, the bounds
// that resampling should keep the spacing within. Throws std::invalid_argument for a
// picture without points.
RenderJob picture_job(const Picture& picture, ImageSize size, const std::optional<OrbitView>& view,
                      RenderOptions options);

}  // namespace amls
