// Rendering with several MPI ranks (`mpirun -np N geovis render ...`): rank 0 hands out the tiles
// of each image to every rank, most expensive first, gathers the finished tiles, checkpoints them
// and writes the files; ranks 1..N-1 render what they are given with their own threads.
//
// Design: rank 0 renders too. Its render threads take tiles straight from the image's queue
// (render/tile_render_session.h), and one extra communication thread answers the other ranks'
// requests. A thread is needed because rank 0's render threads are busy for the whole length of
// a tile: a rank that asks for work would otherwise wait up to a tile's time, and the other ranks
// would idle at every tile boundary. The communication thread polls (MPI_Iprobe, then sleeps
// 100 microseconds) instead of blocking in MPI, which keeps it from spinning a core that a render
// thread needs. Every MPI call of a process is made under one mutex, so MPI_THREAD_SERIALIZED is
// enough. A rank's request carries the tile it just finished (pixels and cost), so one round trip
// per tile both returns the result and fetches the next work.
//
// A tile's pixels do not depend on which rank or thread renders it: the image is byte-identical
// to a single-process render for any number of ranks and threads.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "render/render_job.h"
#include "render/tile_render_session.h"

namespace geovis {

class MpiContext {
 public:
  /// The MPI job this process was started in, or null when it was not started by an MPI launcher
  /// (Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE; srun and other launchers PMI_SIZE / PMIX_RANK).
  /// Without such a launch MPI is never initialized, so geovis never needs mpirun. Throws Error
  /// when launched by mpirun with several ranks but built without MPI.
  static std::unique_ptr<MpiContext> from_environment();
  ~MpiContext();  ///< MPI_Finalize

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Ends the whole job at once (MPI_Abort): for rank 0 after it has reported an error.
  [[noreturn]] void abort(int code);
  /// A rank other than 0 failed: `message` goes to rank 0, which reports it (once, even when all
  /// ranks fail the same way) and ends the job. Waits for that end.
  [[noreturn]] void fail(const std::string& message);

  /// "mpirun -np N <this command line> --resume": how to continue the job.
  std::string resume_command() const;

 private:
  MpiContext(int rank, int size) : rank_(rank), size_(size) {}
  int rank_ = 0, size_ = 1;
};

/// Rank 0's side: hands the tiles of each image to ranks 1..N-1 until finish().
class MpiTileDispatcher final : public TileDistributor {
 public:
  explicit MpiTileDispatcher(MpiContext& mpi);
  ~MpiTileDispatcher() override;
  void start_image(ImageInProgress& image) override;
  void end_image() override;
  /// No more images: tells every rank to stop and waits until they have.
  void finish();

  struct State;

 private:
  std::unique_ptr<State> state_;
};

/// Ranks 1..N-1: renders the tiles rank 0 hands out, with `options.threads` threads, until rank 0
/// has no more; `job_for(frame, eye)` builds the job of an image (called once per image).
void run_mpi_worker(MpiContext& mpi, const RenderOptions& options,
                    const std::function<const RenderJob&(int frame, int eye)>& job_for);

}  // namespace geovis
