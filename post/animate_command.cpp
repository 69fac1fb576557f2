// `isopound-post animate` (see animate_command.h).
#include "post/animate_command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "post/animation3d.h"
#include "post/command_support.h"
#include "post/headless.h"
#include "post/paraview_run.h"
#include "post/paraview_view.h"
#include "post/render_png.h"
#include "post/vtu_writer.h"

namespace fs = std::filesystem;

namespace isopound::post {
namespace {

// Frames an earlier `animate` wrote into this directory: the files its animation.pvd lists that
// are named as isopound names frames (a user's own files are never touched).
void remove_old_frames(const fs::path& out_dir) {
  std::ifstream pvd(out_dir / "animation.pvd");
  const std::regex listed(R"re(file="(frame_[0-9]{6}\.vtu)")re");
  std::string line;
  std::smatch m;
  while (std::getline(pvd, line))
    if (std::regex_search(line, m, listed)) fs::remove(out_dir / m[1].str());
}

// --render: the animation through view.py in pvpython, headless: `png` (every frame as
// OUT/png/frame.NNNN.png), `video` (OUT/animation.avi) or a .avi / .ogv / .png path.
void render_with_paraview(const fs::path& out_dir, const std::string& render) {
  std::vector<std::string> args;
  fs::path target;
  const std::string ext = fs::path(render).extension().string();
  if (render == "png" || ext == ".png") {
    target = render == "png" ? out_dir / "png" : fs::path(render).parent_path();
    args = {"--png", target.string()};
  } else if (render == "video" || ext == ".avi" || ext == ".ogv") {
    target = render == "video" ? out_dir / "animation.avi" : fs::path(render);
    args = {"--video", target.string()};
  } else {
    throw BadInput("--render '" + render + "': write png, video, or a .png, .avi or .ogv path");
  }
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path());
  std::fflush(stdout);
  const PrivateDisplay display;
  try {
    run_pvpython(out_dir / "view.py", args);
  } catch (const ParaViewError& e) {
    throw std::runtime_error(std::string("--render: ") + e.what());
  }
  std::printf("Rendered with ParaView into %s\n", target.string().c_str());
}

}  // namespace

int run_animate(const std::string& dir, const std::string& out, const std::string& model,
                const AnimateArgs& a) {
  const AnimationOptions& opt = a.frame;
  const TimelineOptions& tl = a.timeline;
  if (!(opt.scale > 0.0) || !std::isfinite(opt.scale)) throw BadInput("--scale: must be > 0");
  if (!(tl.fps > 0.0) || !std::isfinite(tl.fps)) throw BadInput("--fps: must be > 0");
  if (!(opt.force_length > 0.0) || !std::isfinite(opt.force_length))
    throw BadInput("--force-length: must be > 0");
  if (tl.frames_per_episode < kMinFramesPerEpisode)
    throw BadInput("--impact-frames: must be >= " + std::to_string(kMinFramesPerEpisode));
  if (tl.max_frames < 2) throw BadInput("--max-frames: must be >= 2");
  if (a.exaggeration < 0.0 || (a.exaggeration > 0.0 && a.exaggeration < 1.0) ||
      !std::isfinite(a.exaggeration))
    throw BadInput("--exaggerate: must be >= 1 (0: automatic)");
  if (a.view_scale < 0.0 || !std::isfinite(a.view_scale))
    throw BadInput("--view-scale: must be > 0 (0: automatic)");
  const RunData run = load_run(dir, model);
  const fs::path out_dir = out.empty() ? fs::path(dir) / "animation" : fs::path(out);
  fs::create_directories(out_dir);
  if (a.preview > run.time().back())
    throw BadInput("--preview " + std::to_string(a.preview) + " s: after the end of the run (" +
                   std::to_string(run.time().back()) + " s)");
  if (tl.start < 0.0 || (tl.end >= 0.0 && tl.end < tl.start) || tl.start > run.time().back())
    throw BadInput("--start/--end: need 0 <= start <= end, start before the end of the run (" +
                   std::to_string(run.time().back()) + " s)");
  Timeline line;
  try {
    line = frame_timeline(run, tl);
  } catch (const TimelineError& e) {
    throw BadInput(e.what());
  }
  if (!line.note.empty()) std::fprintf(stderr, "isopound-post: note: %s\n", line.note.c_str());
  remove_old_frames(out_dir);
  std::vector<std::string> files;
  std::fflush(stdout);
  Progress progress("frames", line.times.size());
  double extent = 0.0;         // the drawing's size, for the automatic exaggeration and scale
  double largest = 0.0;        // m, the largest displacement of a point in any frame
  std::size_t in_contact = 0;  // frames with a contact cell
  for (std::size_t k = 0; k < line.times.size(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.vtu", k);
    FrameMesh frame = animation_frame(run, line.times[k], opt);
    frame.field_data.push_back({"slow_motion", 1, {line.slow_motion[k]}});
    if (k == 0) {
      std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
      for (const auto& p : frame.points)
        for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
      for (int i = 0; i < 3; ++i) extent = std::max(extent, hi[i] - lo[i]);
    }
    for (const MeshArray& d : frame.point_data)
      if (d.name == "displacement")
        for (std::size_t i = 0; i + 2 < d.values.size(); i += 3)
          largest = std::max(largest, std::hypot(d.values[i], d.values[i + 1], d.values[i + 2]));
    for (const MeshArray& b : frame.cell_data)
      if (b.name == "block")
        in_contact +=
            std::count(b.values.begin(), b.values.end(), static_cast<double>(Block::kContact)) > 0;
    write_vtu(frame, (out_dir / name).string());
    files.push_back(name);
    progress.tick(k + 1);
  }
  write_text(out_dir / "animation.pvd", pvd_text(line.times, files));

  ViewScriptOptions view;
  view.absolute_dir = fs::absolute(out_dir).lexically_normal().string();
  view.three_d = run.three_d;
  view.frame_scale = opt.scale;
  view.frame_gaps_scaled = !run.three_d;
  view.scale = a.view_scale > 0.0 ? a.view_scale : automatic_scale(largest, extent);
  view.fps = line.fps;
  view.force_length = opt.force_length;
  view.peaks = contact_peaks(run);
  // 2D frames draw gaps and overlaps × scale; 3D overlaps are drawn true.
  view.exaggeration = a.exaggeration > 0.0 ? a.exaggeration
                                           : automatic_exaggeration(
                                                 view.peaks, run.three_d ? 1.0 : opt.scale, extent);
  write_text(out_dir / "view.py", view_script(view));

  std::printf("Wrote %s/animation.pvd and %zu frames (%.4g s to %.4g s, %g frames/s",
              out_dir.string().c_str(), files.size(), line.times.front(), line.times.back(),
              line.fps);
  if (line.uniform)
    std::printf(", uniform");
  else if (line.episodes == 0)
    std::printf("; no contact episode");
  else
    std::printf("; %zu contact episodes, %d frames each, slow motion up to x%.0f", line.episodes,
                line.frames_per_episode,
                *std::max_element(line.slow_motion.begin(), line.slow_motion.end()));
  std::printf("; %zu show a contact; scale %g)\n", in_contact, opt.scale);
  std::printf(
      "view.py draws displacements x %g (the largest, %.3g m, as %.2g m of the site's %.3g m",
      view.scale, largest, view.scale * largest, extent);
  if (a.view_scale > 0.0) std::printf(", --view-scale");
  const ForceUnit unit = force_unit(view.peaks);
  std::printf("), contact overlaps x %g, contact forces in %s (peak %.3g %s)\n", view.exaggeration,
              unit.name, view.peaks.normal_force / unit.newtons, unit.name);
  std::printf("Wrote %s/view.py: open it with  paraview --script=%s/view.py\n",
              out_dir.string().c_str(), out_dir.string().c_str());
  if (a.preview >= 0.0) {
    std::fflush(stdout);
    const PrivateDisplay display;
    const FrameMesh frame = animation_frame(run, a.preview, opt);
    render_png(run.three_d ? frame_figure3d(frame, opt.scale) : frame_figure(frame, opt.scale),
               (out_dir / "preview.png").string());
    std::printf("Wrote %s/preview.png (t = %g s)\n", out_dir.string().c_str(), a.preview);
  }
  if (!a.render.empty()) render_with_paraview(out_dir, a.render);
  return kOk;
}

}  // namespace isopound::post
