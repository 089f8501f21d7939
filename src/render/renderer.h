// The renderer: the film is split into tiles (16x16 by default) that `threads` worker threads take
// from a TileSchedule (render/tile_schedule.h; render() takes them in order from an atomic
// counter); every pixel is computed independently of which thread traces it, so the output does
// not depend on the schedule. Types in render/render_job.h.
#pragma once

#include "core/error.h"
#include "render/render_job.h"

namespace geovis {

/// render() stopped because RenderOptions::cancel was set; nothing of the frame is returned.
class RenderInterrupted : public Error {
 public:
  RenderInterrupted(int tiles_done, int tiles_total);
  int tiles_done() const { return tiles_done_; }
  int tiles_total() const { return tiles_total_; }

 private:
  int tiles_done_, tiles_total_;
};

/// Renders one image (and the filter data). Throws Error for an inconsistent job or a frame that
/// does not fit in memory (render/frame_limits.h); an error thrown while tracing stops all
/// workers and is rethrown.
RenderResult render(const RenderJob& job, const RenderOptions& options = {});

class TileSchedule;

/// An empty result for `job`: the image at the camera resolution and, when the filter stores
/// data, room for them. Throws Error when the job has no camera or an empty resolution.
RenderResult allocate_render_result(const RenderJob& job);

/// Renders the tiles that `schedule` hands out into `result` (from allocate_render_result; other
/// pixels are left as they are) with `options.threads` threads, and adds the ray statistics to
/// result.stats. The checkpointed and distributed renders (render/tile_render_session.h) use it.
void render_tiles(const RenderJob& job, const RenderOptions& options, TileSchedule& schedule, RenderResult& result);

/// Sample positions of n x n supersampling inside the unit pixel square (stratified centres
/// ((a + .5)/n, (b + .5)/n)); n = 1 gives the pixel centre (.5, .5).
void supersample_offsets(int n, int a, int b, double& ox, double& oy);

}  // namespace geovis
