// Rendering with several MPI ranks (`mpirun -np N geovis render ...`): rank 0 hands out the tiles
// of the images in flight (render/tile_render_session.h) to every rank, most expensive first and
// the oldest image first, gathers the finished tiles, checkpoints them and writes the files;
// ranks 1..N-1 render what they are given with their own threads. Frames are not a barrier: a
// rank that finds no tile of frame N left is given one of frame N+1 while N's last tiles finish
// and rank 0 writes N.
//
// Design: rank 0 renders too. Its render threads take tiles straight from the images' queues
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

/// Rank 0's side: hands the tiles of the session's images in flight to ranks 1..N-1, oldest image
/// first (so a rank that finds no tile of frame N left gets one of frame N+1), until finish().
class MpiTileDispatcher {
 public:
  /// `session` must outlive the dispatcher.
  MpiTileDispatcher(MpiContext& mpi, TileRenderSession& session);
  ~MpiTileDispatcher();
  /// An image was submitted to or taken back from the session: updates the message printed when
  /// the job is stopped.
  void images_changed();
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
