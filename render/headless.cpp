#include "render/headless.hpp"

#include <stdexcept>
#include <string>

#include "core/util/parameter_ranges.hpp"
#include "render/offscreen_context.hpp"

namespace amls {

namespace {

constexpr int kMaxSupersample = static_cast<int>(ranges::kSupersample.max);
constexpr int kMaxImageSide = static_cast<int>(ranges::kImageSide.max);

// Each pixel of the result is the mean of a factor x factor block of `large` (rounded to nearest).
Image box_downsample(const Image& large, int factor) {
  Image small;
  small.width = large.width / factor;
  small.height = large.height / factor;
  small.rgba.resize(4 * static_cast<std::size_t>(small.width) * static_cast<std::size_t>(small.height));
  const int count = factor * factor;
  for (int y = 0; y < small.height; ++y)
    for (int x = 0; x < small.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx) sum += large.pixel(x * factor + dx, y * factor + dy)[c];
        small.rgba[4 * (static_cast<std::size_t>(y) * small.width + x) + c] =
            static_cast<std::uint8_t>((sum + count / 2) / count);
      }
  return small;
}

}  // namespace

Image render_offscreen(const RenderJob& job, const std::function<void(SplatRenderer&)>& fill,
                       HeadlessGlInfo* gl_used) {
  const int s = job.supersample;
  if (s < 1 || s > kMaxSupersample)
    throw std::invalid_argument("supersampling factor must be from 1 to " + std::to_string(kMaxSupersample) + ", got " +
                                std::to_string(s));
  if (job.width > 0 && job.height > 0 && (job.width > kMaxImageSide / s || job.height > kMaxImageSide / s))
    throw std::invalid_argument("image " + std::to_string(job.width) + "x" + std::to_string(job.height) +
                                " supersampled " + std::to_string(s) + " times exceeds " +
                                std::to_string(kMaxImageSide) + " pixels a side");
  OffscreenContext context(job.width * s, job.height * s,
                           job.gl ? *job.gl : headless_gl_choice_from_environment());
  if (gl_used != nullptr) *gl_used = context.info();
  SplatRenderer renderer;
  fill(renderer);
  const BoundingSphere bounds = renderer.bounds();
  if (bounds.empty()) throw std::invalid_argument("nothing to render: the scene is empty");

  Camera camera = job.camera.value_or(renderer.dimension() == 2 ? Camera::planar() : Camera::orbit());
  const Viewport viewport = context.viewport();
  if (job.framing == Framing::fit) camera.fit(bounds, viewport.aspect());
  if (job.framing == Framing::center) camera.center_on(bounds);
  RenderOptions options = job.options;
  const auto factor = static_cast<float>(s);
  options.point_size_px *= factor;
  options.handle_size_px *= factor;
  options.line_width_px *= factor;
  renderer.draw(camera, viewport, options);
  const Image image = read_framebuffer(viewport);
  return s == 1 ? image : box_downsample(image, s);
}

HeadlessGlInfo render_to_png(const std::filesystem::path& png, const RenderJob& job,
                             const std::function<void(SplatRenderer&)>& fill) {
  HeadlessGlInfo gl_used;
  write_png(png, render_offscreen(job, fill, &gl_used));
  return gl_used;
}

template <int D>
HeadlessGlInfo render_to_png(const std::filesystem::path& png, const RenderJob& job, const PointSet<D>& points,
                             std::optional<double> spacing) {
  if (points.empty()) throw std::invalid_argument("cannot render an empty point set");
  return render_to_png(png, job, [&](SplatRenderer& renderer) {
    const PointUpload upload = renderer.set_points(points, spacing);
    if (upload.drawn == 0)
      throw std::invalid_argument("cannot render: none of the " + std::to_string(points.size()) +
                                  " points has a finite position and a non-zero finite normal");
  });
}

template HeadlessGlInfo render_to_png<2>(const std::filesystem::path&, const RenderJob&, const PointSet<2>&,
                                         std::optional<double>);
template HeadlessGlInfo render_to_png<3>(const std::filesystem::path&, const RenderJob&, const PointSet<3>&,
                                         std::optional<double>);

}  // namespace amls
