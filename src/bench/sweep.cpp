#include "bench/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "app/headless_frames.h"
#include "bench/accuracy.h"
#include "core/error_metrics.h"
#include "core/presets.h"
#include "core/settings_schema.h"
#include "gfx/offscreen_target.h"

namespace reflect {

namespace {

// Rough mirrors (the rough-spheres scene; docs/rough.md): one knob at a time around the default,
// at the scene's own face size: the narrow lobes' rays, or taps for them too (the default before
// narrow lobes were traced); one distance for a whole lobe (before each quarter was searched); the
// lobe taps; the prefiltered levels instead (the split sum
// everywhere, the default before lobe taps), with their samples and levels; the face size; and
// the traced lobe's rays (the exact mode).
void appendRoughSettings(std::vector<SweepSetting>& s) {
  const AccuracySettings shipped;
  s.push_back({"rough-default", shipped, 0});
  for (int n : {0, 4, 16}) {
    AccuracySettings a = shipped;
    a.narrowLobeRays = n;
    s.push_back(
        {n == 0 ? std::string("rough-narrow-taps") : "rough-narrow-rays-" + std::to_string(n), a,
         0});
  }
  AccuracySettings oneDistance = shipped;
  oneDistance.lobeQuarters = false;
  s.push_back({"rough-one-distance", oneDistance, 0});
  for (int n : {4, 8, 32}) {
    AccuracySettings a = shipped;
    a.lobeTaps = n;
    s.push_back({"rough-taps-" + std::to_string(n), a, 0});
  }
  AccuracySettings prefiltered = shipped;
  prefiltered.lobeTaps = 0;
  prefiltered.narrowLobeRays = 0;
  s.push_back({"rough-prefiltered", prefiltered, 0});
  for (int n : {4, 8, 16, 64, 128}) {
    AccuracySettings a = prefiltered;
    a.filterSamples = n;
    s.push_back({"rough-samples-" + std::to_string(n), a, 0});
  }
  for (int n : {1, 2, 3, 8}) {
    AccuracySettings a = prefiltered;
    a.roughLevels = n;
    s.push_back({"rough-levels-" + std::to_string(n), a, 0});
  }
  for (int size : {32, 64, 256}) s.push_back({"rough-size-" + std::to_string(size), shipped, size});
  AccuracySettings plain = shipped;
  plain.search = Search::Plain;
  s.push_back({"rough-plain", plain, 0});
  AccuracySettings hierarchical = shipped;
  hierarchical.search = Search::Hierarchical;
  s.push_back({"rough-hierarchical", hierarchical, 0});
  for (int n : {4, 16, 64}) {
    AccuracySettings a{.search = Search::Exact};
    a.lobeRays = n;
    s.push_back({"rough-exact-rays-" + std::to_string(n), a, 0});
  }
}

}  // namespace

std::vector<SweepSetting> sweepSettings() {
  // The course's settings are the preset's, so that the sweep, the CLI and the page measure one
  // definition of it.
  const Preset* course = findPreset("course");
  const AccuracySettings shipped;  // the default: planned (traced or captured, per reflector)
  AccuracySettings hierarchical;   // the cube-map search with two layers (the default before)
  hierarchical.search = Search::Hierarchical;
  AccuracySettings centre = hierarchical;  // plain lookup from the reflector's centre
  centre.search = Search::Plain;
  AccuracySettings linear = hierarchical;  // the search this project shipped first
  linear.search = Search::Linear;
  AccuracySettings oneLayer = hierarchical;
  oneLayer.layers = 1;

  std::vector<SweepSetting> s = {{"original", course->accuracy, 256, course->planner},
                                 {"default", shipped, 256},
                                 {"hierarchical", hierarchical, 256},
                                 {"centre", centre, 256},
                                 {"linear", linear, 256},
                                 {"layers-1", oneLayer, 256},
                                 {"exact", AccuracySettings{.search = Search::Exact}, 256}};
  for (int size : {32, 64, 128, 512, 1024})
    s.push_back({"size-" + std::to_string(size), centre, size});
  for (int size : {64, 128, 512})
    s.push_back({"hierarchical-size-" + std::to_string(size), hierarchical, size});
  AccuracySettings a = centre;
  a.depthBits = 16;
  s.push_back({"depth-16", a, 256});
  a = centre;
  a.mipmaps = true;
  s.push_back({"mipmapped", a, 256});
  a = centre;
  a.halfFloat = true;
  s.push_back({"rgba16f", a, 256});
  a = hierarchical;
  a.halfFloat = true;
  s.push_back({"hierarchical-rgba16f", a, 256});
  a = centre;
  a.mediump = true;
  s.push_back({"mediump", a, 256});
  a = hierarchical;
  a.mediump = true;
  s.push_back({"hierarchical-mediump", a, 256});
  a = shipped;
  a.mediump = true;
  s.push_back({"default-mediump", a, 256});
  appendRoughSettings(s);
  return s;
}

Result<std::vector<SweepRow>> runSweep(const SweepDemoFactory& makeDemo,
                                       const std::vector<SweepSetting>& settings,
                                       const SweepOptions& o) {
  using Out = Result<std::vector<SweepRow>>;
  std::vector<std::unique_ptr<Demo>> demos;
  for (const SweepSetting& s : settings) {
    auto demo = makeDemo();
    if (!demo) return Out::failure(demo.error());
    demo.value()->setPlannerSettings(s.planner);
    if (s.faceSize > 0) demo.value()->setCubeFaceSize(s.faceSize);
    std::string error = demo.value()->setAccuracySettings(s.accuracy);
    if (error.empty()) error = demo.value()->initGraphics();
    if (!error.empty()) return Out::failure(s.name + ": " + error);
    demos.push_back(demo.take());
  }

  // Timing: the settings take turns a block of frames at a time (headless_frames.h), after a
  // warm-up block each.
  Result<OffscreenTarget> target = OffscreenTarget::create(o.width, o.height);
  if (!target) return Out::failure(target.error());
  std::vector<Demo*> timed;
  for (auto& d : demos) timed.push_back(d.get());
  const auto step = [](size_t) { return 1.0 / 60.0; };
  timeInBlocks(timed, target.value().framebuffer(), o.width, o.height, 3, step);
  const std::vector<TimedFrames> frames =
      timeInBlocks(timed, target.value().framebuffer(), o.width, o.height, o.frames, step);
  std::vector<std::vector<double>> ms(settings.size()), cpu(settings.size());
  for (size_t i = 0; i < settings.size(); ++i) {
    ms[i] = frames[i].ms;
    cpu[i] = frames[i].cpuMs;
  }

  // One reference per time and capture point, shared by every setting that captures there.
  std::map<std::pair<double, bool>, ReferenceFrame> references;
  const auto referenceAt = [&](Demo& demo, double t) -> Result<const ReferenceFrame*> {
    const auto key = std::make_pair(t, demo.accuracySettings().captureAtOrigin);
    auto it = references.find(key);
    if (it == references.end()) {
      Result<ReferenceFrame> frame = referenceFor(demo, t, o.width, o.height, o.reference);
      if (!frame) return Result<const ReferenceFrame*>::failure(frame.error());
      it = references.emplace(key, frame.take()).first;
    }
    return &it->second;
  };

  std::vector<SweepRow> rows;
  for (size_t i = 0; i < settings.size(); ++i) {
    SweepRow row;
    row.setting = settings[i];
    row.medianMs = median(ms[i]);
    row.p10Ms = percentile(ms[i], 0.1);
    row.p90Ms = percentile(ms[i], 0.9);
    row.cpuMs = median(cpu[i]);
    row.captureMs = median(frames[i].captureMs);
    row.filterMs = median(frames[i].filterMs);
    row.irradianceMs = median(frames[i].irradianceMs);
    double heldOutMse = 0, tunedMse = 0, p95 = 0, angle = 0, offMse = 0, visible = 0;
    std::map<int, double> roughMse;  // by object
    row.worstPsnrDb = kPsnrCapDb;
    for (bool heldOut : {true, false}) {
      for (double t : heldOut ? o.heldOutTimes : o.tunedTimes) {
        Result<const ReferenceFrame*> reference = referenceAt(*demos[i], t);
        if (!reference) return Out::failure(settings[i].name + ": " + reference.error());
        auto report = measureAccuracy(*demos[i], t, o.width, o.height, reference.value());
        if (!report) return Out::failure(settings[i].name + ": " + report.error());
        const AccuracyReport& r = report.value();
        const double mse = r.reflector.rmse * r.reflector.rmse;
        if (!heldOut) {
          tunedMse += mse / static_cast<double>(o.tunedTimes.size());
          continue;
        }
        heldOutMse += mse / static_cast<double>(o.heldOutTimes.size());
        for (const auto& [object, metrics] : r.perReflector) {
          if (!demos[i]->scene().objects[static_cast<size_t>(object)].rough()) continue;
          roughMse[object] +=
              metrics.rmse * metrics.rmse / static_cast<double>(o.heldOutTimes.size());
        }
        offMse += r.offReflector.rmse * r.offReflector.rmse;
        p95 += r.reflector.p95PixelError;
        row.maxError = std::max(row.maxError, static_cast<double>(r.reflector.maxPixelError));
        angle += r.meanAngularErrorDeg;
        visible += static_cast<double>(r.reflector.visibleErrorPixels);
        row.worstVisible =
            std::max(row.worstVisible, static_cast<double>(r.reflector.visibleErrorPixels));
        row.worstPsnrDb = std::min(row.worstPsnrDb, r.reflector.psnrDb);
      }
    }
    const double n = static_cast<double>(o.heldOutTimes.size());
    row.rmse = std::sqrt(heldOutMse);
    row.psnrDb = psnrFromRmse(row.rmse);
    row.tunedPsnrDb = o.tunedTimes.empty() ? std::nan("") : psnrFromRmse(std::sqrt(tunedMse));
    row.offReflectorPsnrDb = psnrFromRmse(std::sqrt(offMse / n));
    row.p95 = p95 / n;
    row.meanAngularErrorDeg = angle / n;
    row.visiblePerFrame = visible / n;
    for (const auto& [object, mse] : roughMse) {
      char label[48];
      std::snprintf(label, sizeof label, "roughness %g",
                    demos[i]->scene().objects[static_cast<size_t>(object)].roughness);
      row.roughPsnrDb.emplace_back(label, psnrFromRmse(std::sqrt(mse)));
    }
    rows.push_back(row);
    demos[i].reset();
  }
  // On the front: no other row is both faster and more accurate. (Two rows with the same
  // pictures, e.g. the default where it traces and the exact mode, tie on accuracy: the one a
  // millisecond faster in this run is not better, the machine's noise is.)
  for (SweepRow& r : rows) {
    r.pareto = std::none_of(rows.begin(), rows.end(), [&](const SweepRow& other) {
      return &other != &r && other.medianMs < r.medianMs && other.psnrDb > r.psnrDb;
    });
  }
  return rows;
}

std::string sweepTable(const std::vector<SweepRow>& rows) {
  std::string out =
      "| name | setting | face | frame ms median (p10-p90) | CPU ms | reflector PSNR dB (worst "
      "time) | pixels > 32 per frame (worst) | RMSE | p95 | max | mean angular error deg | "
      "off-reflector PSNR dB | PSNR at tuning times | Pareto |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char line[640];
  for (const SweepRow& r : rows) {
    char tuned[32] = "-";  // not measured
    if (!std::isnan(r.tunedPsnrDb)) std::snprintf(tuned, sizeof tuned, "%.2f", r.tunedPsnrDb);
    std::snprintf(line, sizeof line,
                  "| %s | %s | %d | %.2f (%.2f-%.2f) | %.2f | %.2f (%.2f) | %.1f (%.0f) | %.2f | "
                  "%.1f | %.0f | %.3f | %.1f | %s | %s |\n",
                  r.setting.name.c_str(), r.setting.accuracy.describe().c_str(), r.setting.faceSize,
                  r.medianMs, r.p10Ms, r.p90Ms, r.cpuMs, r.psnrDb, r.worstPsnrDb, r.visiblePerFrame,
                  r.worstVisible, r.rmse, r.p95, r.maxError, r.meanAngularErrorDeg,
                  r.offReflectorPsnrDb, tuned, r.pareto ? "yes" : "");
    out += line;
  }
  return out;
}

namespace {

// A CSV field in quotes, with its quotes doubled.
std::string csvQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string sweepCsv(const std::vector<SweepRow>& rows) {
  std::string out =
      "name,setting,settings,face_size,ms,ms_p10,ms_p90,psnr_db,rmse,p95,max,"
      "mean_angular_error_deg,off_reflector_psnr_db,pareto,cpu_ms,worst_psnr_db,"
      "visible_per_frame,worst_visible,tuned_psnr_db\n";
  char numbers[320];
  for (const SweepRow& r : rows) {
    std::snprintf(numbers, sizeof numbers,
                  "%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.3f,%.0f,%.4f,%.3f,%d,%.4f,%.4f,%.2f,%.0f,%.4f\n",
                  r.setting.faceSize, r.medianMs, r.p10Ms, r.p90Ms, r.psnrDb, r.rmse, r.p95,
                  r.maxError, r.meanAngularErrorDeg, r.offReflectorPsnrDb, r.pareto ? 1 : 0,
                  r.cpuMs, r.worstPsnrDb, r.visiblePerFrame, r.worstVisible, r.tunedPsnrDb);
    out += r.setting.name + "," + csvQuoted(r.setting.accuracy.describe()) + "," +
           csvQuoted(settingsJson(r.setting.accuracy, accuracyFields()).dump()) + "," + numbers;
  }
  return out;
}

std::string sweepSvg(const std::vector<SweepRow>& rows) {
  const double width = 760, height = 460, left = 70, right = 200, top = 30, bottom = 60;
  double minMs = 1e9, maxMs = 0, minDb = 1e9, maxDb = 0;
  for (const SweepRow& r : rows) {
    minMs = std::min(minMs, r.medianMs);
    maxMs = std::max(maxMs, r.medianMs);
    minDb = std::min(minDb, r.psnrDb);
    maxDb = std::max(maxDb, r.psnrDb);
  }
  minMs *= 0.9;
  maxMs *= 1.05;
  minDb = std::floor(minDb - 1);
  maxDb = std::ceil(maxDb + 1);
  auto x = [&](double ms) {
    return left + (ms - minMs) / (maxMs - minMs) * (width - left - right);
  };
  auto y = [&](double db) {
    return height - bottom - (db - minDb) / (maxDb - minDb) * (height - top - bottom);
  };
  std::string svg;
  char buf[512];
  std::snprintf(
      buf, sizeof buf,
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%%\" height=\"100%%\" "
      "fill=\"white\"/>\n",
      width, height);
  svg += buf;
  std::snprintf(
      buf, sizeof buf,
      "<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"black\"/>\n"
      "<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"black\"/>\n"
      "<text x=\"%.0f\" y=\"%.0f\" text-anchor=\"middle\">frame ms (median, every-frame "
      "capture, lower is faster)</text>\n"
      "<text x=\"16\" y=\"%.0f\" transform=\"rotate(-90 16 %.0f)\" text-anchor=\"middle\">"
      "reflector PSNR vs ray-traced reference, dB (higher is better)</text>\n",
      left, height - bottom, width - right, height - bottom, left, top, left, height - bottom,
      (left + width - right) / 2, height - 20, (top + height - bottom) / 2,
      (top + height - bottom) / 2);
  svg += buf;
  for (int i = 0; i <= 5; ++i) {
    const double ms = minMs + (maxMs - minMs) * i / 5.0, db = minDb + (maxDb - minDb) * i / 5.0;
    std::snprintf(buf, sizeof buf,
                  "<text x=\"%.1f\" y=\"%.0f\" text-anchor=\"middle\">%.1f</text>\n"
                  "<text x=\"%.0f\" y=\"%.1f\" text-anchor=\"end\">%.1f</text>\n",
                  x(ms), height - bottom + 16, ms, left - 6, y(db) + 4, db);
    svg += buf;
  }
  std::vector<const SweepRow*> front;
  for (const SweepRow& r : rows) {
    if (r.pareto) front.push_back(&r);
  }
  std::sort(front.begin(), front.end(), [](auto* a, auto* b) { return a->medianMs < b->medianMs; });
  std::string points;
  for (const SweepRow* r : front) {
    std::snprintf(buf, sizeof buf, "%.1f,%.1f ", x(r->medianMs), y(r->psnrDb));
    points += buf;
  }
  svg += "<polyline fill=\"none\" stroke=\"#d33\" stroke-width=\"2\" points=\"" + points + "\"/>\n";
  for (const SweepRow& r : rows) {
    const bool special = r.setting.name == "original" || r.setting.name == "default";
    std::snprintf(buf, sizeof buf,
                  "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%d\" fill=\"%s\"/>\n"
                  "<text x=\"%.1f\" y=\"%.1f\"%s>%s</text>\n",
                  x(r.medianMs), y(r.psnrDb), special ? 5 : 3, r.pareto ? "#d33" : "#557",
                  x(r.medianMs) + 6, y(r.psnrDb) - 4, special ? " font-weight=\"bold\"" : "",
                  r.setting.name.c_str());
    svg += buf;
  }
  std::snprintf(buf, sizeof buf,
                "<text x=\"%.0f\" y=\"%.0f\" fill=\"#d33\">red line: Pareto front</text>\n</svg>\n",
                width - right + 10, top + 10);
  svg += buf;
  return svg;
}

}  // namespace reflect
