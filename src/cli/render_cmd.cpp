// `geovis render [SCENE] [-o OUT] [--frames A:B] [--res WxH] [--threads N] [--supersample N]
//                [--texture-path DIR]... [--define NAME=VALUE]... [--strict] [--resume]
//                [--movie out.mp4] [--tile-size N] [--schedule cost|stripes] [--tile-stats FILE] [--data]
//                [--quiet] [--verbose]
//                [scene options: cli/scene_options.h]`
//
// Evaluates the scene (the built-in one without SCENE), builds each device (= frame) and renders
// it. Every finished frame is written atomically (io/image.h), in frame order, so a failure in
// frame N never loses frames < N, and --resume continues an interrupted sequence. Inside a frame,
// finished tiles go to a checkpoint next to the image (render/tile_checkpoint.h), from which
// --resume continues an interrupted frame. Under mpirun the ranks share the tiles of up to three
// images in flight (render/mpi_scheduler.h); rank 0 writes the files.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/command.h"
#include "cli/interrupt.h"
#include "cli/render_outputs.h"
#include "cli/scene_options.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image.h"
#include "render/camera.h"
#include "render/data_exr.h"
#include "render/data_files.h"
#include "render/frame_limits.h"
#include "render/mpi_scheduler.h"
#include "render/renderer.h"
#include "render/tile_render_session.h"
#include "scene/builder.h"
#include "scene/default_scene.h"
#include "scene/scheme.h"

extern char** environ;

namespace geovis::cli {

namespace {

namespace fs = std::filesystem;

struct RenderArgs {
  std::string scene;
  std::string out;
  std::string frames;
  std::string res;
  int threads = 0;
  int tile_size = 16;
  int supersample = 1;
  std::vector<std::string> texture_paths;
  SceneArgs scene_args;
  bool strict = false;
  bool resume = false;
  std::string movie;
  std::string tile_stats;
  std::string schedule = "cost";
  bool data = false;  ///< write the EXR data file without a data filter
  bool quiet = false;
  bool verbose = false;
};

// ---- output names ------------------------------------------------------------------------------

/// Position and width of the single printf frame conversion (%d, %4d, %04d) in `pattern`;
/// npos when there is none. "%%" is a literal percent sign; any other '%' use is an error.
struct FramePattern {
  size_t pos = std::string::npos, len = 0;
  int width = 0;
  bool zero = false;
};

FramePattern find_frame_pattern(const std::string& s) {
  FramePattern fp;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') continue;
    if (i + 1 < s.size() && s[i + 1] == '%') {
      ++i;
      continue;
    }
    size_t j = i + 1;
    bool zero = false;
    if (j < s.size() && s[j] == '0') {
      zero = true;
      ++j;
    }
    int width = 0;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) width = width * 10 + (s[j++] - '0');
    if (j >= s.size() || s[j] != 'd' || width > 12)
      throw Error("-o: \"" + s + "\": expected a frame-number pattern like %d or %04d after '%'");
    if (fp.pos != std::string::npos) throw Error("-o: \"" + s + "\": more than one frame-number pattern");
    fp.pos = i;
    fp.len = j + 1 - i;
    fp.width = width;
    fp.zero = zero;
    i = j;
  }
  return fp;
}

std::string format_frame(const std::string& s, const FramePattern& fp, int frame) {
  std::string num = std::to_string(frame);
  if (static_cast<int>(num.size()) < fp.width) num.insert(0, fp.width - num.size(), fp.zero ? '0' : ' ');
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (i == fp.pos) {
      out += num;
      i += fp.len - 1;
    } else if (s[i] == '%' && i + 1 < s.size() && s[i + 1] == '%') {
      out += '%';
      ++i;
    } else {
      out += s[i];
    }
  }
  return out;
}

/// "dir/name.ext" -> ("dir/name", ".ext"); the extension is that of the file name only.
std::pair<std::string, std::string> split_ext(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1) return {path, ""};
  return {path.substr(0, dot), path.substr(dot)};
}

void check_image_extension(const std::string& path) {
  const std::string ext = to_lower(split_ext(path).second);
  static const std::vector<std::string> ok = {".png", ".tif", ".tiff", ".ppm", ".exr", ".jpg", ".jpeg"};
  if (std::find(ok.begin(), ok.end(), ext) == ok.end())
    throw Error("-o: \"" + path +
                "\": " + (ext.empty() ? std::string("no file extension") : "unsupported image format \"" + ext + "\"") +
                "; use .png, .tif or .ppm (also .exr, .jpg)");
}

/// Where frame `frame` goes: OUT's pattern filled in; without a pattern, for a sequence the frame
/// number is inserted before the extension (out_0007.png); a single frame is OUT exactly.
std::string frame_path(const std::string& out, int frame, bool sequence) {
  const FramePattern fp = find_frame_pattern(out);
  if (fp.pos != std::string::npos) return format_frame(out, fp, frame);
  if (!sequence) return out;
  auto [base, ext] = split_ext(out);
  char num[32];
  std::snprintf(num, sizeof num, "_%04d", frame);
  return base + num + ext;
}

/// The ffmpeg input pattern of the frames (printf style, as ffmpeg's image2 demuxer reads it).
std::string movie_pattern(const std::string& out, bool sequence) {
  const FramePattern fp = find_frame_pattern(out);
  if (fp.pos != std::string::npos) return out;
  if (!sequence) return out;
  auto [base, ext] = split_ext(out);
  return base + "_%04d" + ext;
}

/// Stereo images: name.left.ext / name.right.ext.
std::string eye_path(const std::string& path, const std::string& eye) {
  if (eye.empty()) return path;
  auto [base, ext] = split_ext(path);
  return base + "." + eye + ext;
}

bool exists(const std::string& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

// ---- argument parsing --------------------------------------------------------------------------

std::pair<int, int> parse_frames(const std::string& s, int count) {
  auto parse_int = [&](const std::string& t) {
    if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos)
      throw Error("--frames: expected A:B or N with non-negative integers, found \"" + s + "\"");
    try {
      return std::stoi(t);
    } catch (const std::exception&) {
      throw Error("--frames: number out of range in \"" + s + "\"");
    }
  };
  int a, b;
  const size_t colon = s.find(':');
  if (colon == std::string::npos) {
    a = b = parse_int(s);
  } else {
    a = parse_int(s.substr(0, colon));
    b = parse_int(s.substr(colon + 1));
  }
  if (a > b) throw Error("--frames: the first frame " + std::to_string(a) + " is after the last " + std::to_string(b));
  if (b >= count)
    throw Error("--frames: frame " + std::to_string(b) + " does not exist: the scene has " + std::to_string(count) +
                " frame(s), numbered 0 to " + std::to_string(count - 1));
  return {a, b};
}

std::pair<int, int> parse_res(const std::string& s) {
  const size_t x = s.find_first_of("xX");
  auto bad = [&]() -> std::pair<int, int> {
    throw Error("--res: expected WIDTHxHEIGHT (e.g. 640x480), found \"" + s + "\"");
  };
  if (x == std::string::npos) return bad();
  const std::string w = s.substr(0, x), h = s.substr(x + 1);
  if (w.empty() || h.empty() || w.find_first_not_of("0123456789") != std::string::npos ||
      h.find_first_not_of("0123456789") != std::string::npos)
    return bad();
  auto side = [&](const std::string& digits, const char* name) {
    if (digits.size() > 18)  // beyond long long; far beyond the limit
      throw Error("--res " + s + ": the " + name + " " + digits + " is larger than the limit of " +
                  std::to_string(kMaxImageSide) + " pixels per side");
    return std::stoll(digits);
  };
  const long long wi = side(w, "width"), hi = side(h, "height");
  check_frame_size("--res " + s, wi, hi, false);
  return {int(wi), int(hi)};
}

/// Writes `text` to stderr in one stdio call. The progress line of a finished frame is printed by
/// the render session's worker thread while this thread checks and submits the next frames; one
/// call holds the stream's lock for the whole text, a chain of << does not (a line of one thread
/// was cut apart by a line of the other).
void print_err(const std::string& text) { std::fputs(text.c_str(), stderr); }

/// Prints new warnings once (a camera is rebuilt for every frame and would repeat its own).
void print_warnings(Diagnostics& diag, bool quiet, std::set<std::string>& printed) {
  for (const auto& w : diag.warnings())
    if (printed.insert(w).second && !quiet) print_err(w + "\n");
  diag.clear();
}

// ---- ffmpeg ------------------------------------------------------------------------------------

std::string find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    const std::string p = dir + "/" + name;
    if (::access(p.c_str(), X_OK) == 0) return p;
  }
  return {};
}

/// Runs a program with arguments (no shell); returns its exit status (-1 when it could not run).
int run_program(const std::vector<std::string>& args, bool quiet) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (quiet) {
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid;
  const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void make_movie(const RenderArgs& a, const std::string& ffmpeg, const std::string& pattern, int first, bool quiet) {
  // ffmpeg writes a temporary file (same extension, so it picks the same container), which
  // replaces the movie only when complete.
  AtomicFile movie(a.movie);
  // yuv420p needs even dimensions: pad by one pixel when needed.
  const std::vector<std::string> args = {ffmpeg,
                                         "-y",
                                         "-loglevel",
                                         "error",
                                         "-framerate",
                                         "25",
                                         "-start_number",
                                         std::to_string(first),
                                         "-f",
                                         "image2",
                                         "-i",
                                         pattern,
                                         "-vf",
                                         "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                                         "-pix_fmt",
                                         "yuv420p",
                                         movie.temp_path()};
  const int rc = run_program(args, false);
  if (rc != 0)
    throw Error("--movie: ffmpeg failed (exit status " + std::to_string(rc) + ") making \"" + a.movie +
                "\"; the frames are kept");
  movie.commit();
  if (!quiet) std::cerr << "movie: " << a.movie << "\n";
}

// ---- outputs: folders, --resume, interruption ----------------------------------------------------

/// Creates the folders of the first frame and the movie, checks that they are writable, and
/// removes temporary files that killed runs left there.
void prepare_output_folders(const std::vector<std::string>& outputs, bool quiet) {
  for (const std::string& o : outputs) {
    if (o.empty()) continue;
    for (const std::string& stale : prepare_output_folder(fs::path(o).parent_path().string()))
      if (!quiet) std::cerr << "removed \"" << stale << "\", a temporary file left by an interrupted run\n";
  }
}

/// Everything besides the frame number that determines the pixels; its hash goes into every image
/// so that --resume recognises frames of other settings. (Files the scene loads or textures it
/// reads are not included: a changed texture is not detected.)
std::vector<std::string> render_settings(const RenderArgs& a, const std::string& scene_text) {
  std::vector<std::string> s = {"geovis render 1", scene_text};
  for (const auto& d : a.scene_args.defines) s.push_back("--define " + d);
  s.push_back("--res " + a.res);
  s.push_back("--supersample " + std::to_string(a.supersample));
  if (a.data) s.push_back("--data");
  for (const auto& t : a.texture_paths) s.push_back("--texture-path " + t);
  return s;
}

std::string frame_description(std::vector<std::string> settings, int frame, const std::string& eye) {
  settings.push_back("frame " + std::to_string(frame) + " " + eye);
  return settings_description(settings);
}

/// --resume: true when every image of the frame is complete; otherwise says (one line) why the
/// frame is rendered again, unless no image of it exists yet.
bool frame_is_complete(const std::string& path, int frame, const std::vector<FrameJob>& jobs,
                       const std::vector<std::string>& settings, bool quiet) {
  for (const FrameJob& fj : jobs) {
    const ResumeCheck c = check_resume(eye_path(path, fj.eye), fj.job.camera->width(), fj.job.camera->height(),
                                       frame_description(settings, frame, fj.eye));
    if (c.skip) continue;
    if (!c.why.empty() && !quiet)
      print_err("--resume: frame " + std::to_string(frame) + " is rendered again: " + c.why + "\n");
    return false;
  }
  return true;
}

/// SIGINT/SIGTERM stopped the render of `frame`: says so (and where the finished tiles are kept for
/// --resume) and returns 128 + the signal.
int report_interrupted(const RenderInterrupted& e, int signal_number, int frame, int frames_written,
                       const std::string& checkpoint) {
  std::ostringstream msg;
  msg << "geovis: " << e.what() << ", nothing written";
  if (!checkpoint.empty() && fs::exists(checkpoint))
    msg << "; the finished tiles are in \"" << checkpoint << "\" (--resume continues from them)";
  if (frames_written > 0)
    msg << " (frame " << frame << "; the " << frames_written << " frame(s) before it are complete)";
  msg << "\n";
  print_err(msg.str());
  return 128 + (signal_number > 0 ? signal_number : SIGINT);
}

// ---- tiles: checkpoints, MPI ranks, statistics ----------------------------------------------------

RenderOptions tile_render_options(const RenderArgs& a, bool quiet, const std::atomic<bool>* cancel = nullptr) {
  RenderOptions ro;
  ro.cancel = cancel;
  ro.threads = a.threads;
  ro.tile_size = a.tile_size;
  ro.progress = !quiet;
  return ro;
}

/// Submits image `eye` of frame `frame` to the session, with its tile checkpoint IMG.tiles
/// (restored with --resume); the caller removes the checkpoint once the image is written.
void submit_frame_image(TileRenderSession& session, const RenderArgs& a, const std::string& identity, int frame,
                        int eye, const FrameJob& fj, const std::string& img, bool quiet) {
  CheckpointSpec ckpt;
  ckpt.path = img + ".tiles";
  const std::string key = identity + "\nframe " + std::to_string(frame) + " " + fj.eye;
  ckpt.hash = fnv1a64(key.data(), key.size());
  ckpt.resume = a.resume;
  std::string notes;
  const std::string label = "frame " + std::to_string(frame) + (fj.eye.empty() ? "" : " " + fj.eye) + " -> " + img;
  session.submit(frame, eye, fj.job, label, ckpt, &notes);
  if (!quiet) print_err(notes);
}

/// --tile-stats: one CSV line per rendered tile; with --verbose under MPI, each rank's busy CPU time.
void report_tiles(const RenderArgs& a, const TileRenderSession& session, bool verbose, bool mpi) {
  const std::vector<TileLogEntry>& log = session.tile_log();
  if (!a.tile_stats.empty()) {
    std::ostringstream csv;
    csv << "frame,eye,tile,x0,y0,x1,y1,rank,order_cost,cpu_seconds,steps,done_at\n";
    for (const TileLogEntry& e : log)
      csv << e.frame << ',' << e.eye << ',' << e.tile << ',' << e.rect.x0 << ',' << e.rect.y0 << ',' << e.rect.x1 << ','
          << e.rect.y1 << ',' << e.rank << ',' << e.order_cost << ',' << e.cost.cpu_seconds << ',' << e.cost.steps
          << ',' << e.done_at << '\n';
    write_file_atomic(a.tile_stats, csv.str());
  }
  if (!verbose || !mpi) return;
  std::map<int, std::pair<int, double>> per_rank;  // rank -> tiles, CPU seconds
  for (const TileLogEntry& e : log) {
    ++per_rank[e.rank].first;
    per_rank[e.rank].second += e.cost.cpu_seconds;
  }
  for (const auto& [rank, busy] : per_rank)
    std::cerr << "rank " << rank << ": " << busy.first << " tiles, " << busy.second << " s CPU\n";
}

/// Ranks 1..N-1 of an MPI job: render the tiles rank 0 hands out, building each frame's jobs
/// when its first tile arrives.
int render_as_mpi_worker(SceneBuilder& builder, const RenderArgs& a, MpiContext& mpi) {
  int built = -1;
  std::vector<FrameJob> jobs;
  run_mpi_worker(mpi, tile_render_options(a, true), [&](int frame, int eye) -> const RenderJob& {
    if (frame != built) {
      jobs = builder.build(frame);
      for (FrameJob& fj : jobs) fj.job.keep_data = a.data;
      built = frame;
    }
    if (eye < 0 || size_t(eye) >= jobs.size())
      throw Error("MPI: frame " + std::to_string(frame) + " has no image " + std::to_string(eye));
    return jobs[size_t(eye)].job;
  });
  return 0;
}

// ---- the command -------------------------------------------------------------------------------

int run_render(const RenderArgs& a, const GlobalOptions& g, MpiContext* mpi) {
  const bool mpi_worker = mpi && mpi->rank() > 0;  // only rank 0 prints and writes
  const bool quiet = a.quiet || g.quiet || mpi_worker;
  const bool verbose = (a.verbose || g.verbose) && !quiet;
  Diagnostics diag;
  diag.strict = a.strict;
  std::set<std::string> printed;

  // Check the arguments that need no scene first (fail fast, before a long evaluation).
  std::optional<std::pair<int, int>> res;
  if (!a.res.empty()) res = parse_res(a.res);
  if (a.threads < 0)
    throw Error("--threads: expected 0 (all cores) or a positive number, found " + std::to_string(a.threads));
  if (a.tile_size < 1 || a.tile_size > 4096)
    throw Error("--tile-size: expected 1 to 4096 pixels, found " + std::to_string(a.tile_size));
  if (a.supersample < 1 || a.supersample > kMaxSupersample)
    throw Error("--supersample: expected 1 to " + std::to_string(kMaxSupersample) + " samples per pixel side, found " +
                std::to_string(a.supersample));
  if (!a.movie.empty() && to_lower(split_ext(a.movie).second).empty())
    throw Error("--movie: \"" + a.movie + "\": expected a file name with an extension such as .mp4");
  // Look for ffmpeg before rendering, so that a long render does not fail at its very end.
  std::string ffmpeg;
  if (!a.movie.empty() && (ffmpeg = find_program("ffmpeg")).empty())
    throw Error(
        "--movie: ffmpeg is not installed (not found in PATH); install it (Debian: apt-get install "
        "ffmpeg) or render without --movie and assemble the frames yourself");
  for (const auto& dir : a.texture_paths)
    if (!fs::is_directory(dir)) throw Error("--texture-path: \"" + dir + "\" is not a directory");

  const SchemeOptions sopts = scheme_options(a.scene_args, &diag, quiet);
  SceneDescription scene;
  std::string base;
  DataFileInfo data_info;
  data_info.version = kVersion;
  for (const auto& d : a.scene_args.defines) data_info.defines += (data_info.defines.empty() ? "" : " ") + d;
  std::string scene_text;  // read once: the data files' scene hash and the --resume settings
  if (a.scene.empty()) {
    scene = evaluate_scene_string(default_scene_text(), default_scene_name() + ".scm", sopts);
    base = default_scene_name();
    scene_text = default_scene_text();
  } else {
    if (!fs::exists(a.scene)) throw Error("scene file \"" + a.scene + "\" does not exist");
    scene = evaluate_scene_file(a.scene, sopts);
    base = fs::path(a.scene).stem().string();
    std::ifstream text(a.scene, std::ios::binary);
    std::stringstream ss;
    ss << text.rdbuf();
    scene_text = ss.str();
    data_info.scene_file = fs::path(a.scene).filename().string();
    data_info.scene_path = fs::absolute(a.scene).lexically_normal().string();
  }
  data_info.scene_hash = fnv1a_hex(scene_text);
  print_warnings(diag, quiet, printed);

  BuildOptions bopts;
  const std::string scene_dir = a.scene.empty() ? std::string() : fs::path(a.scene).parent_path().string();
  bopts.search_paths.push_back(scene_dir.empty() ? "." : scene_dir);
  for (const auto& t : a.texture_paths) bopts.search_paths.push_back(t);
  bopts.search_paths.push_back(".");
  bopts.resolution = res;
  bopts.supersample = a.supersample;
  bopts.diag = &diag;
  set_action_output(bopts, a.scene_args);
  SceneBuilder builder(std::move(scene), bopts);
  print_warnings(diag, quiet, printed);

  require_devices(builder);
  const int count = builder.device_count();
  if (count > kMaxFrames)
    throw Error("the scene has " + std::to_string(count) + " frames (init-device); the limit is " +
                std::to_string(kMaxFrames));
  auto [first, last] = a.frames.empty() ? std::pair<int, int>{0, count - 1} : parse_frames(a.frames, count);
  // Several frames: OUT is a pattern or gets the frame number; one frame goes to OUT exactly.
  // The default name is numbered whenever the scene is a sequence.
  const bool sequence = last > first;
  const std::string out = a.out.empty() ? base + (count > 1 ? "_%04d.png" : ".png") : a.out;
  find_frame_pattern(out);  // validates the pattern
  check_image_extension(out);
  // Before anything is rendered: an unwritable folder is found now, not after the first frame.
  prepare_output_folders({frame_path(out, first, sequence), a.movie}, quiet);
  const std::vector<std::string> settings = render_settings(a, scene_text);

  std::ostringstream action_log;
  builder.run_actions(action_log);
  if (!quiet) std::cout << action_log.str();
  if (mpi_worker) return render_as_mpi_worker(builder, a, *mpi);

  // SIGINT/SIGTERM stop at the next tile. Under mpirun, SIGTERM is mpirun ending the job (a rank
  // died, a time limit): the MPI dispatcher's own handler then says where the job stood instead.
  std::optional<InterruptHandler> interrupt;
  if (!mpi) interrupt.emplace();
  // Under MPI up to three images are in flight, so that ranks that run out of tiles of one frame
  // start on the next while its last tiles finish and it is written (memory: three results).
  // Alone, one image at a time: an interrupted render then has exactly one unfinished frame.
  // --schedule stripes: GeoViS's fixed bands of rows, one per rank, to measure what cost ordering gains.
  const int stripes = a.schedule == "stripes" ? (mpi ? mpi->size() : 1) : 0;
  TileRenderSession session(tile_render_options(a, quiet, interrupt ? interrupt->flag() : nullptr), mpi ? 3 : 1,
                            stripes);
  std::unique_ptr<MpiTileDispatcher> dispatcher;
  if (mpi) dispatcher = std::make_unique<MpiTileDispatcher>(*mpi, session);
  std::string identity;  // what a tile checkpoint must match: the same settings as the images' hash
  for (const std::string& line : settings) identity += line + "\n";
  int rendered = 0, skipped = 0;
  bool stereo = false;

  // The images submitted and not yet written, oldest first; their jobs live here until then.
  struct PendingImage {
    int frame = 0;
    size_t eye = 0;
    std::shared_ptr<const std::vector<FrameJob>> jobs;
    std::string img;
  };
  std::deque<PendingImage> pending;
  // Writes the oldest image once it is complete; returns the exit status when the render was
  // interrupted.
  auto write_oldest = [&]() -> std::optional<int> {
    const PendingImage p = pending.front();
    const FrameJob& fj = (*p.jobs)[p.eye];
    RenderedImage rendered_image;
    try {
      rendered_image = session.take_oldest();
    } catch (const RenderInterrupted& e) {
      return report_interrupted(e, interrupt ? interrupt->signal_number() : 0, p.frame, rendered + skipped,
                                p.img + ".tiles");
    }
    pending.pop_front();
    if (dispatcher) dispatcher->images_changed();
    const RenderResult& r = rendered_image.result;
    const std::string& img = p.img;
    // Data files first, the image last: an existing image means a complete frame (--resume).
    if (!fj.data_files_wanted.empty()) {
      const std::string written = write_filter_data(img, fj.job.filter, r.image.width, r.image.height, r.data);
      if (verbose && !written.empty()) print_err("  data: " + written + "\n");
    }
    if (!r.data.empty()) {
      data_info.frame = p.frame;
      const std::string written = write_data_exr(img, fj.job, r.image, r.data, data_info);
      if (verbose) print_err("  data: " + written + "\n");
    }
    write_image(img, r.image, 8, frame_description(settings, p.frame, fj.eye));
    if (rendered_image.checkpoint) rendered_image.checkpoint->remove();
    if (verbose) {
      std::ostringstream msg;
      msg << "  " << img << ": tiles: " << rendered_image.tiles_rendered << " rendered, "
          << rendered_image.tiles_restored << " restored from the checkpoint";
      if (mpi)
        msg << "; " << rendered_image.later_tiles_started
            << " tiles of later images were handed out before its last tile was done";
      msg << "\n  " << r.stats.rays << " rays, " << r.stats.steps << " steps, " << r.stats.rhs_evals
          << " right-hand-side evaluations, " << r.stats.seconds << " s\n";
      print_err(msg.str());
    }
    if (p.eye + 1 == p.jobs->size()) ++rendered;
    return std::nullopt;
  };

  for (int f = first; f <= last; ++f) {
    const std::string path = frame_path(out, f, sequence);
    auto jobs = std::make_shared<std::vector<FrameJob>>(builder.build(f));
    for (FrameJob& fj : *jobs) fj.job.keep_data = a.data;
    stereo = stereo || jobs->size() == 2;
    print_warnings(diag, quiet, printed);
    if (a.resume && frame_is_complete(path, f, *jobs, settings, quiet)) {
      ++skipped;
      if (verbose) print_err("frame " + std::to_string(f) + ": " + path + " is complete, skipped (--resume)\n");
      continue;
    }
    for (size_t eye = 0; eye < jobs->size(); ++eye) {
      const FrameJob& fj = (*jobs)[eye];
      const std::string img = eye_path(path, fj.eye);
      const fs::path parent = fs::path(img).parent_path();
      if (!parent.empty()) {
        std::error_code ec;
        fs::create_directories(parent, ec);
        if (ec) throw Error("cannot create the output folder \"" + parent.string() + "\": " + ec.message());
      }
      while (session.full())
        if (const std::optional<int> rc = write_oldest()) return *rc;
      submit_frame_image(session, a, identity, f, int(eye), fj, img, quiet);
      pending.push_back({f, eye, jobs, img});
      if (dispatcher) dispatcher->images_changed();
    }
  }
  while (!pending.empty())
    if (const std::optional<int> rc = write_oldest()) return *rc;
  if (dispatcher) dispatcher->finish();
  report_tiles(a, session, verbose, mpi != nullptr);
  if (!quiet && a.resume)
    print_err(std::to_string(rendered) + " frame(s) rendered, " + std::to_string(skipped) + " skipped (already on disk)\n");

  if (!a.movie.empty()) {
    // A stereo sequence becomes the movie of the left eye.
    stereo = stereo || exists(eye_path(frame_path(out, first, sequence), "left"));
    make_movie(a, ffmpeg, eye_path(movie_pattern(out, sequence), stereo ? "left" : ""), first, quiet);
  }
  return 0;
}

/// Runs the command in this process or, under mpirun, as one rank of an MPI job. An error ends
/// the whole job and is reported once: by rank 0, or by rank 0 on behalf of the rank that failed.
int run_render_in_mpi_job(const RenderArgs& a, const GlobalOptions& g) {
  const std::unique_ptr<MpiContext> mpi = MpiContext::from_environment();
  if (!mpi || mpi->size() == 1) return run_render(a, g, nullptr);
  try {
    return run_render(a, g, mpi.get());
  } catch (const SceneExit& e) {
    if (mpi->rank() > 0) return e.code();  // every rank stops at the scene's (exit); rank 0 says so
    throw;
  } catch (const std::exception& e) {
    if (mpi->rank() > 0) mpi->fail(e.what());
    std::cerr << "geovis: error: " << e.what() << "\n";
    mpi->abort(1);
  }
}

void setup_render(CLI::App& app, GlobalOptions& g) {
  auto a = std::make_shared<RenderArgs>();
  CLI::App* sub = app.add_subcommand("render", "render a scene (the built-in scene without SCENE)");
  sub->add_option("scene", a->scene, "GeoViS scene file (.scm)");
  sub->add_option("-o,--output", a->out,
                  "output image (.png, .tif, .ppm); for several frames a printf pattern like seq_%04d.png");
  sub->add_option("--frames", a->frames, "frames to render: A:B (inclusive) or N; default all");
  sub->add_option("--res", a->res, "override the camera resolution, WIDTHxHEIGHT (field of view kept)");
  sub->add_option("--threads", a->threads, "worker threads (0 = all cores)");
  sub->add_option("--supersample", a->supersample, "N x N samples per pixel");
  sub->add_option("--tile-size", a->tile_size,
                  "tiles of N x N pixels that threads and MPI ranks take one at a time (default 16)");
  sub->add_option("--texture-path", a->texture_paths,
                  "extra folder to search for textures and meshes (a file the scene names by a path that "
                  "does not exist here is looked up by its file name)")
      ->allow_extra_args(false);
  add_scene_options(sub, a->scene_args);
  sub->add_flag("--strict", a->strict, "treat warnings (unknown keys, ...) as errors");
  sub->add_flag("--resume", a->resume,
                "skip frames whose image already exists and continue a frame from its tile checkpoint");
  sub->add_option("--movie", a->movie, "assemble the frames into a movie with ffmpeg (e.g. out.mp4)");
  sub->add_option("--schedule", a->schedule,
                  "how tiles are handed out: cost (default: most expensive first, to whoever is free) or "
                  "stripes (one fixed band of rows per MPI rank, as GeoViS does; for load-balance comparisons)")
      ->check(CLI::IsMember({"cost", "stripes"}));
  sub->add_option("--tile-stats", a->tile_stats,
                  "write one CSV line per rendered tile (rank, CPU seconds, steps) to FILE, for load-balance studies");
  sub->add_flag("--data", a->data,
                "also write the OpenEXR data file (hit event, direction, 1+z, object, stop reason per pixel; "
                "docs/data-format.md) next to each image, as the data filters do");
  sub->add_flag("-q,--quiet", a->quiet, "print nothing but errors");
  sub->add_flag("-v,--verbose", a->verbose, "print details (statistics per frame)");
  sub->callback([a, &g]() {
    try {
      g.exit_code = run_render_in_mpi_job(*a, g);
    } catch (const SceneExit& e) {
      // The scene called (exit [code]): GeoViS stops there without rendering. Not an error;
      // the exit status is the scene's code.
      if (!(a->quiet || g.quiet)) std::cerr << "geovis: " << e.what() << "\n";
      g.exit_code = e.code();
    }  // other errors reach run() (app.cpp), which reports them and sets the exit status
  });
}

const bool render_registered = register_command("render", &setup_render);

}  // namespace

}  // namespace geovis::cli
