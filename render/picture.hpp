#pragma once
// A picture without GL: the renderer's content (points with their spacing h,
// MLS curve, handles, per-point quality) and the view it is seen from.
// app/picture_input.hpp makes one from `amls render`'s input.
//
// Views: a 3D picture is seen in perspective, by default from azimuth 30 and
// elevation 20 degrees (the eye on +z turned 30 degrees towards +x and raised 20
// degrees towards +y; see render/camera.hpp), centred and framed to fit. A 2D
// picture is seen orthographically (x right, y up), centred and framed to fit.
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/util/parameter_ranges.hpp"
#include "render/headless.hpp"
#include "render/splat_renderer.hpp"

namespace amls {

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

// The eye of a 3D picture: azimuth and elevation in degrees, and its distance
// from the centre in world units (none: framed to fit).
struct OrbitView {
  float azimuth_deg = 30.0f;
  float elevation_deg = 20.0f;
  std::optional<float> distance;
};


// The job for a picture: its size, the camera (see the header comment; `view` is
// for 3D pictures only, and throws std::invalid_argument for a 2D one) and options.
// Framing to fit uses the box around everything drawn (points with their splats and
// normals, curve, handles) as seen from the camera, so that elongated shapes fill the
// image; the centre is that box's centre. In 2D, dots are sized to about half the
// spacing on screen (1.5 to 7 px) in a colour apart from the curve's. For
// ColorMode::scalar (quality) the colour range is fixed at the spacing band
// (core/surface/spacing_band.hpp) that resampling should keep the spacing within.
// Throws std::invalid_argument for a picture without points.
RenderJob picture_job(const Picture& picture, ImageSize size, const std::optional<OrbitView>& view,
                      RenderOptions options);

}  // namespace amls
