#include "render/mpi_scheduler.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <map>
#include <set>
#include <mutex>
#include <thread>
#include <vector>

#include "core/error.h"
#include "render/renderer.h"

#if GEOVIS_HAVE_MPI
#include <mpi.h>
#endif

namespace geovis {

namespace {

/// The number of ranks an MPI launcher announced in the environment; 0 without such a launch.
int launcher_world_size() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(var)) return std::max(1, std::atoi(v));
  if (std::getenv("PMIX_RANK") || std::getenv("PMI_RANK")) return 1;
  return 0;
}

std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string out;
  size_t start = 0;
  while (start < raw.size()) {
    size_t end = raw.find('\0', start);
    if (end == std::string::npos) end = raw.size();
    std::string arg = raw.substr(start, end - start);
    if (arg.empty() || arg.find_first_of(" \t'\"$*?&;|<>()") != std::string::npos) arg = "'" + arg + "'";
    out += (out.empty() ? "" : " ") + arg;
    start = end + 1;
  }
  return out;
}

}  // namespace

std::string MpiContext::resume_command() const {
  std::string cmd = command_line();
  if ((" " + cmd + " ").find(" --resume ") == std::string::npos) cmd += " --resume";
  return "mpirun -np " + std::to_string(size_) + " " + cmd;
}

#if GEOVIS_HAVE_MPI

namespace {

/// Every MPI call of the process is made under this mutex (MPI_THREAD_SERIALIZED).
std::mutex& mpi_mutex() {
  static std::mutex m;
  return m;
}

enum Tag : int {
  kTagRequest = 1,  ///< rank -> 0: RequestHeader (+ the finished tile), asks for the next tile
  kTagBye = 2,      ///< rank -> 0: all threads of the rank are done
  kTagError = 3,    ///< rank -> 0: the rank failed; the text of the error
  kTagAssign = 100  ///< 0 -> rank, + the requesting thread's slot: an Assignment
};

struct RequestHeader {
  int32_t slot = 0, frame = -1, eye = -1, tile = -1;  ///< tile -1: no finished tile attached
  double cpu_seconds = 0;
  int64_t steps = 0;
  int32_t n_floats = 0, n_doubles = 0;
  /// A render thread asks for more work of the image it renders (rank 0 answers at once: a tile,
  /// or kNoTileNow when that image has none left); false: the rank waits for the next image.
  int32_t in_image = 0;
  /// 0: the message only returns the finished tile; rank 0 sends nothing back.
  int32_t wants_work = 1;
};

struct Assignment {
  /// kNoTileNow ends a render thread's work on its image. Without it a thread waiting for work
  /// could keep its rank inside an image while a tile of the next image, received by another of
  /// its threads, waits to be rendered: rank 0 would wait for that tile, the rank for work.
  enum Kind : int32_t { kUnknown = -1, kFinished = 0, kTile = 1, kNoTileNow = 2 };
  int32_t kind = kUnknown, frame = -1, eye = -1, tile = -1;
};

/// Polls a non-blocking operation to completion without holding the MPI mutex in between (other
/// threads of the process keep communicating) and without spinning a core.
void wait_for(MPI_Request& request) {
  for (;;) {
    int done = 0;
    {
      std::lock_guard lock(mpi_mutex());
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    }
    if (done) return;
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
}

void send_bytes(const void* data, size_t n, int dest, int tag) {
  MPI_Request r;
  {
    std::lock_guard lock(mpi_mutex());
    MPI_Isend(data, int(n), MPI_BYTE, dest, tag, MPI_COMM_WORLD, &r);
  }
  wait_for(r);
}

// What rank 0 prints when the job is stopped from outside (SIGTERM: mpirun ending the job because
// a rank died, or a batch system's time limit): a signal handler may only write() bytes that are
// ready, so the communication thread keeps the message up to date in one of two buffers and
// publishes it by switching the index.
char g_status[2][8192];
std::atomic<int> g_status_active{-1};

void publish_status(const std::string& text) {
  const int next = g_status_active.load() == 0 ? 1 : 0;
  const size_t n = std::min(text.size(), sizeof g_status[next] - 1);
  std::memcpy(g_status[next], text.data(), n);
  g_status[next][n] = '\0';
  g_status_active.store(next);
}

extern "C" void on_terminate(int sig) {
  const int a = g_status_active.load();
  if (a >= 0) {
    const ssize_t ignored = ::write(2, g_status[a], std::strlen(g_status[a]));
    (void)ignored;
  }
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

std::unique_ptr<MpiContext> MpiContext::from_environment() {
  if (launcher_world_size() == 0) return nullptr;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::unique_ptr<MpiContext> mpi(new MpiContext(rank, size));
  if (provided < MPI_THREAD_SERIALIZED) {
    if (rank == 0)
      std::cerr << "geovis: error: the MPI library does not support threads (MPI_THREAD_SERIALIZED); "
                   "rebuild geovis with Open MPI (Debian: libopenmpi-dev)\n";
    mpi->abort(1);
  }
  return mpi;
}

MpiContext::~MpiContext() {
  std::lock_guard lock(mpi_mutex());
  MPI_Finalize();
}

void MpiContext::abort(int code) {
  std::cerr.flush();
  mpi_mutex().lock();  // never released: the process ends here
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

void MpiContext::fail(const std::string& message) {
  // Rank 0 reports the error and ends the job. When every rank fails the same way (a scene
  // error), rank 0 reports its own and the others stay silent: the error appears once.
  MPI_Request r;
  {
    std::lock_guard lock(mpi_mutex());
    MPI_Isend(message.data(), int(message.size()), MPI_BYTE, 0, kTagError, MPI_COMM_WORLD, &r);
  }
  // Rank 0 may still be evaluating the scene; give it a minute to end the job, then end it here.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::cerr << "geovis: error: rank " << rank_ << ": " << message << "\n";
  abort(1);
}

// ---- rank 0 ------------------------------------------------------------------------------------

struct MpiTileDispatcher::State {
  State(MpiContext& m, TileRenderSession& s) : mpi(m), session(s) {}
  MpiContext& mpi;
  TileRenderSession& session;
  std::thread comm;
  std::atomic<bool> stop{false};
  std::mutex mutex;                         // guards everything below
  std::deque<std::pair<int, int>> waiting;  ///< (rank, slot) asking for work while there is none
  struct Lent {
    int rank, frame, eye, tile;
    auto operator<=>(const Lent&) const = default;
  };
  std::set<Lent> in_flight;  ///< tiles handed out and not back yet
  bool finishing = false;
  int byes = 0;

  void loop();
  void handle_request(int source, const std::vector<char>& msg);
  bool assign(int rank, int slot, bool in_image);
  void serve_waiting();
  void update_status();
  std::string status_text() const;
};

std::string MpiTileDispatcher::State::status_text() const {
  std::string s = "geovis: the MPI job was stopped (a rank died, or the batch system ended it)";
  const char* sep = " while rendering ";
  for (const ImageStatus& im : session.status()) {
    s += sep + std::string("frame ") + std::to_string(im.frame);
    if (im.eye > 0) s += " (image " + std::to_string(im.eye + 1) + " of the stereo pair)";
    s += ": " + std::to_string(im.done) + " of " + std::to_string(im.todo) + " tiles were finished";
    if (!im.checkpoint.empty()) s += " and are kept in the checkpoint \"" + im.checkpoint + "\"";
    sep = "; ";
  }
  if (!in_flight.empty()) {
    s += "; unfinished:";
    for (const Lent& t : in_flight)
      s += " tile " + std::to_string(t.tile) + " of frame " + std::to_string(t.frame) + " on rank " +
           std::to_string(t.rank) + ",";
    s.pop_back();
  }
  return s + "\ngeovis: to continue, run: " + mpi.resume_command() + "\n";
}

void MpiTileDispatcher::State::update_status() { publish_status(status_text()); }

bool MpiTileDispatcher::State::assign(int rank, int slot, bool in_image) {
  Assignment a;
  const ImageTile next = finishing ? ImageTile{} : session.pop(rank);
  if (next.image) {
    a = {Assignment::kTile, next.image->frame, next.image->eye, next.tile};
    in_flight.insert({rank, next.image->frame, next.image->eye, next.tile});
  } else if (finishing) {
    a.kind = Assignment::kFinished;
  } else if (in_image) {
    a.kind = Assignment::kNoTileNow;
  } else {
    waiting.emplace_back(rank, slot);
    return false;
  }
  send_bytes(&a, sizeof a, rank, kTagAssign + slot);
  if (next.image) update_status();
  return true;
}

void MpiTileDispatcher::State::serve_waiting() {
  // A waiting rank that still finds no work goes back into the queue, and the rest wait too.
  while (!waiting.empty()) {
    const auto [rank, slot] = waiting.front();
    waiting.pop_front();
    if (!assign(rank, slot, false)) break;
  }
}

void MpiTileDispatcher::State::handle_request(int source, const std::vector<char>& msg) {
  RequestHeader h;
  if (msg.size() < sizeof h) throw Error("MPI: a short request from rank " + std::to_string(source));
  std::memcpy(&h, msg.data(), sizeof h);
  if (h.tile >= 0) {
    ImageInProgress* image = session.find(h.frame, h.eye);
    if (!image || h.tile >= image->grid.count() || !in_flight.count({source, h.frame, h.eye, h.tile}))
      throw Error("MPI: rank " + std::to_string(source) + " returned tile " + std::to_string(h.tile) + " of frame " +
                  std::to_string(h.frame) + ", which it was not given");
    const int px = image->grid.rect(h.tile).pixels();
    const int doubles_per_px = int(sizeof(PixelData) / sizeof(double));
    if (h.n_floats != 3 * px || (h.n_doubles != 0 && h.n_doubles != px * doubles_per_px) ||
        msg.size() != sizeof h + size_t(h.n_floats) * sizeof(float) + size_t(h.n_doubles) * sizeof(double))
      throw Error("MPI: tile " + std::to_string(h.tile) + " from rank " + std::to_string(source) +
                  " has the wrong size");
    // Copied out of the message: the byte buffer gives no alignment guarantee for float/double.
    std::vector<float> pixels(size_t(h.n_floats));
    std::memcpy(pixels.data(), msg.data() + sizeof h, pixels.size() * sizeof(float));
    std::vector<PixelData> data(size_t(h.n_doubles / doubles_per_px));
    std::memcpy(static_cast<void*>(data.data()), msg.data() + sizeof h + pixels.size() * sizeof(float),
                data.size() * sizeof(PixelData));
    // Out of the list before it counts as done: once done, the image may be written and leave.
    in_flight.erase({source, h.frame, h.eye, h.tile});
    image->done_remote(h.tile, source, TileCost{h.cpu_seconds, long(h.steps)}, pixels.data(),
                       data.empty() ? nullptr : data.data());
  }
  if (!h.wants_work || !assign(source, h.slot, h.in_image != 0)) update_status();
}

void MpiTileDispatcher::State::loop() {
  std::vector<char> msg;
  try {
    while (!stop.load()) {
      int flag = 0;
      MPI_Status st;
      {
        std::lock_guard lock(mpi_mutex());
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      }
      if (!flag) {
        {
          std::lock_guard lock(mutex);
          serve_waiting();
          if (finishing && byes == mpi.size() - 1) return;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        continue;
      }
      int count = 0;
      {
        std::lock_guard lock(mpi_mutex());
        MPI_Get_count(&st, MPI_BYTE, &count);
        msg.resize(size_t(std::max(count, 1)));
        MPI_Recv(msg.data(), count, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      }
      msg.resize(size_t(count));
      std::lock_guard lock(mutex);
      if (st.MPI_TAG == kTagRequest) {
        handle_request(st.MPI_SOURCE, msg);
      } else if (st.MPI_TAG == kTagBye) {
        ++byes;
      } else if (st.MPI_TAG == kTagError) {
        std::cerr << "geovis: error: rank " << st.MPI_SOURCE << ": " << std::string(msg.begin(), msg.end()) << "\n"
                  << status_text();
        mpi.abort(1);
      } else {
        throw Error("MPI: unexpected message (tag " + std::to_string(st.MPI_TAG) + ") from rank " +
                    std::to_string(st.MPI_SOURCE));
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "geovis: error: " << e.what() << "\n" << status_text();
    mpi.abort(1);
  }
}

MpiTileDispatcher::MpiTileDispatcher(MpiContext& mpi, TileRenderSession& session)
    : state_(std::make_unique<State>(mpi, session)) {
  state_->update_status();
  ::signal(SIGTERM, on_terminate);
  state_->comm = std::thread([s = state_.get()] { s->loop(); });
}

MpiTileDispatcher::~MpiTileDispatcher() {
  if (state_->comm.joinable()) {
    state_->stop = true;
    state_->comm.join();
  }
}

void MpiTileDispatcher::images_changed() {
  std::lock_guard lock(state_->mutex);
  state_->update_status();
}

void MpiTileDispatcher::finish() {
  {
    std::lock_guard lock(state_->mutex);
    state_->finishing = true;
  }
  state_->comm.join();
  ::signal(SIGTERM, SIG_DFL);
}

// ---- ranks 1..N-1 ------------------------------------------------------------------------------

namespace {

/// The tiles rank 0 hands to this rank's render threads. A thread's request may be answered with
/// a tile of the next image; it is kept ("stashed") until that image is rendered.
class WorkerTiles final : public TileSchedule {
 public:
  explicit WorkerTiles(int slots) : stash_(size_t(slots)), finished_(size_t(slots)) {}

  void begin_image(int frame, int eye, const TileGrid& grid) {
    frame_ = frame;
    eye_ = eye;
    grid_ = grid;
  }

  /// The image of the earliest stashed tile; false when rank 0 has no more work.
  bool next_image(int& frame, int& eye) {
    for (;;) {
      bool any_finished = false, any_tile = false;
      for (const Assignment& a : stash_) {
        any_finished = any_finished || a.kind == Assignment::kFinished;
        if (a.kind == Assignment::kTile && (!any_tile || std::make_pair(a.frame, a.eye) < std::make_pair(frame, eye))) {
          frame = a.frame;
          eye = a.eye;
          any_tile = true;
        }
      }
      if (any_tile) return true;
      if (any_finished) return false;
      stash_[0] = request(0, false);
    }
  }

  int next_tile(int slot) override {
    // A finished tile goes back with the thread's next request; when the thread takes a stashed
    // tile instead, or may not ask (it keeps a tile of a later image), it goes back at once, before
    // the thread finishes another tile in its place.
    int stashed = -1;
    bool keeps_later = false;
    {
      std::lock_guard lock(mutex_);
      for (Assignment& a : stash_) {
        if (a.kind == Assignment::kTile && a.frame == frame_ && a.eye == eye_) {
          a.kind = Assignment::kUnknown;
          stashed = a.tile;
          break;
        }
      }
      keeps_later = stashed < 0 && stash_[size_t(slot)].kind != Assignment::kUnknown;
    }
    if (stashed >= 0 || keeps_later) {
      return_finished(slot);
      return stashed;
    }
    const Assignment a = request(slot, true);
    if (a.kind == Assignment::kTile && a.frame == frame_ && a.eye == eye_) return a.tile;
    if (a.kind == Assignment::kNoTileNow) return -1;
    std::lock_guard lock(mutex_);
    stash_[size_t(slot)] = a;
    return -1;
  }

  void tile_done(int slot, int tile, const TileCost& cost, const RenderResult& result) override {
    const TileRect r = grid_.rect(tile);
    const bool with_data = !result.data.empty();
    RequestHeader h;
    h.slot = slot;
    h.frame = frame_;
    h.eye = eye_;
    h.tile = tile;
    h.cpu_seconds = cost.cpu_seconds;
    h.steps = cost.steps;
    h.n_floats = 3 * r.pixels();
    h.n_doubles = with_data ? r.pixels() * int(sizeof(PixelData) / sizeof(double)) : 0;
    h.in_image = 1;
    std::vector<char>& out = finished_[size_t(slot)];
    out.assign(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    for (int y = r.y0; y < r.y1; ++y) {
      const char* row = reinterpret_cast<const char*>(result.image.at(r.x0, y));
      out.insert(out.end(), row, row + size_t(r.x1 - r.x0) * 3 * sizeof(float));
    }
    if (with_data)
      for (int y = r.y0; y < r.y1; ++y) {
        const char* row = reinterpret_cast<const char*>(&result.data[size_t(y) * grid_.width + r.x0]);
        out.insert(out.end(), row, row + size_t(r.x1 - r.x0) * sizeof(PixelData));
      }
    test_hook_tile_finished();
  }

 private:
  /// Returns the thread's finished tile, if any, to rank 0 without asking for work.
  void return_finished(int slot) {
    std::vector<char>& msg = finished_[size_t(slot)];
    if (msg.empty()) return;
    RequestHeader h;
    std::memcpy(&h, msg.data(), sizeof h);
    h.wants_work = 0;
    std::memcpy(msg.data(), &h, sizeof h);
    send_bytes(msg.data(), msg.size(), 0, kTagRequest);
    msg.clear();
  }

  /// Returns the thread's finished tile (if any) to rank 0 and receives its next assignment;
  /// `in_image`: asked by a render thread of the current image.
  Assignment request(int slot, bool in_image) {
    std::vector<char>& msg = finished_[size_t(slot)];
    if (msg.empty()) {
      RequestHeader h;
      h.slot = slot;
      h.in_image = in_image ? 1 : 0;
      msg.assign(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    }
    Assignment a;
    MPI_Request recv;
    {
      std::lock_guard lock(mpi_mutex());
      MPI_Irecv(&a, sizeof a, MPI_BYTE, 0, kTagAssign + slot, MPI_COMM_WORLD, &recv);
    }
    send_bytes(msg.data(), msg.size(), 0, kTagRequest);
    msg.clear();
    wait_for(recv);
    return a;
  }

  std::mutex mutex_;  // guards stash_
  std::vector<Assignment> stash_;
  std::vector<std::vector<char>> finished_;  ///< per slot: the request carrying its last tile
  int frame_ = -1, eye_ = -1;
  TileGrid grid_;
};

}  // namespace

void run_mpi_worker(MpiContext& mpi, const RenderOptions& options,
                    const std::function<const RenderJob&(int frame, int eye)>& job_for) {
  (void)mpi;
  const int slots = std::max(1, options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency()));
  WorkerTiles tiles(slots);
  RenderOptions ro = options;
  ro.threads = slots;
  ro.progress = false;
  int frame = -1, eye = -1;
  while (tiles.next_image(frame, eye)) {
    const RenderJob& job = job_for(frame, eye);
    RenderResult result = allocate_render_result(job);
    tiles.begin_image(frame, eye, TileGrid(result.image.width, result.image.height, ro.tile_size));
    render_tiles(job, ro, tiles, result);
  }
  const int32_t bye = 0;
  send_bytes(&bye, sizeof bye, 0, kTagBye);
}

#else  // built without MPI

std::unique_ptr<MpiContext> MpiContext::from_environment() {
  if (launcher_world_size() > 1)
    throw Error(
        "geovis was built without MPI, so every rank would render the whole job; run it without "
        "mpirun, or rebuild with Open MPI (Debian: libopenmpi-dev)");
  return nullptr;
}
MpiContext::~MpiContext() = default;
void MpiContext::abort(int code) { std::_Exit(code); }
void MpiContext::fail(const std::string& message) {
  std::cerr << "geovis: error: " << message << "\n";
  std::_Exit(1);
}
struct MpiTileDispatcher::State {};
MpiTileDispatcher::MpiTileDispatcher(MpiContext&, TileRenderSession&) { throw Error("geovis was built without MPI"); }
MpiTileDispatcher::~MpiTileDispatcher() = default;
void MpiTileDispatcher::images_changed() {}
void MpiTileDispatcher::finish() {}
void run_mpi_worker(MpiContext&, const RenderOptions&, const std::function<const RenderJob&(int, int)>&) {
  throw Error("geovis was built without MPI");
}

#endif

}  // namespace geovis
