#include "render/headless.hpp"

#include <stdexcept>
#include <string>

#include "render/offscreen_context.hpp"

namespace amls {

Image render_offscreen(const RenderJob& job, const std::function<void(SplatRenderer&)>& fill) {
  OffscreenContext context(job.width, job.height);
  SplatRenderer renderer;
  fill(renderer);
  const BoundingSphere bounds = renderer.bounds();
  if (bounds.empty()) throw std::invalid_argument("nothing to render: the scene is empty");

  Camera camera = job.camera.value_or(renderer.dimension() == 2 ? Camera::planar() : Camera::orbit());
  const Viewport viewport = context.viewport();
  if (job.framing == Framing::fit) camera.fit(bounds, viewport.aspect());
  if (job.framing == Framing::center) camera.center_on(bounds);
  renderer.draw(camera, viewport, job.options);
  return read_framebuffer(viewport);
}

void render_to_png(const std::filesystem::path& png, const RenderJob& job,
                   const std::function<void(SplatRenderer&)>& fill) {
  write_png(png, render_offscreen(job, fill));
}

template <int D>
void render_to_png(const std::filesystem::path& png, const RenderJob& job, const PointSet<D>& points,
                   std::optional<double> spacing) {
  if (points.empty()) throw std::invalid_argument("cannot render an empty point set");
  render_to_png(png, job, [&](SplatRenderer& renderer) {
    const PointUpload upload = renderer.set_points(points, spacing);
    if (upload.drawn == 0)
      throw std::invalid_argument("cannot render: none of the " + std::to_string(points.size()) +
                                  " points has a finite position and a non-zero finite normal");
  });
}

template void render_to_png<2>(const std::filesystem::path&, const RenderJob&, const PointSet<2>&,
                               std::optional<double>);
template void render_to_png<3>(const std::filesystem::path&, const RenderJob&, const PointSet<3>&,
                               std::optional<double>);

}  // namespace amls
