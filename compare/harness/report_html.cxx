// report_html.cxx - index.html and the wrong_pct plot. Every string that
// comes from a scene (ids, descriptions, errors, reasons) goes through
// HtmlEscape; names reach gnuplot only as data.
#include "report.h"

#include "harness_files.h"
#include "harness_process.h"
#include "harness_progress.h"
#include "harness_text.h"
#include "scene_list.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <unistd.h>

namespace vsh_harness
{

bool WritePlot(
  const Options& opt, const std::vector<SceneResult>& all, const std::vector<std::string>& tests)
{
  std::string dat = "scene";
  for (const auto& t : tests)
    dat += " " + t;
  dat += "\n";
  for (const SceneResult& sr : all)
  {
    dat += SafeName(sr.entry.id);
    for (const auto& t : tests)
    {
      double worst = -1;
      for (const Row& r : sr.rows)
        if (r.test == t && r.status != "error")
          worst = std::max(worst, r.m.wrong_pct);
      dat += worst < 0 ? " NaN" : " " + Fmt(std::max(worst, 1e-4), "%.6g");
    }
    dat += "\n";
  }
  std::string err;
  if (!WriteFileAtomic(opt.out + "/plot.dat", dat, err))
    return false;
  // Fixed script text; names reach gnuplot only as data (column headers),
  // printed as given (noenhanced: the '_' of soft_samples is no subscript).
  std::string gp =
    "set terminal pngcairo size 1400,600 font 'sans,9'\n"
    "set output 'wrong_pct.png.tmp'\n"
    "set title 'wrong\\_pct (worst light) against POV-Ray, per scene; log scale, floor 1e-4'\n"
    "set style data histogram\nset style histogram cluster gap 1\n"
    "set style fill solid border -1\nset boxwidth 0.9\nset logscale y\nset yrange [1e-4:100]\n"
    "set ylabel 'wrong pixels (%)'\nset xtics rotate by -45 scale 0\nset key outside right top\n"
    "set grid ytics\nset datafile missing 'NaN'\n"
    "plot for [i=2:" +
    std::to_string(tests.size() + 1) +
    "] 'plot.dat' using i:xtic(1) title columnheader(i) noenhanced\n";
  if (!WriteFileAtomic(opt.out + "/wrong_pct.gp", gp, err))
    return false;
  RunResult r = RunProcess({ "gnuplot", "wrong_pct.gp" }, opt.out, opt.out + "/gnuplot.log", 120);
  if (!r.ok() ||
    rename((opt.out + "/wrong_pct.png.tmp").c_str(), (opt.out + "/wrong_pct.png").c_str()) != 0)
  {
    unlink((opt.out + "/wrong_pct.png.tmp").c_str());
    Progress("WARNING: plot not made (gnuplot: " + r.error + "; apt-get install gnuplot-nox)");
    return false;
  }
  return true;
}

namespace
{

std::string Header(bool plot)
{
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>vtkshadow-compare"
                  "</title><style>body{font-family:sans-serif;margin:1em}table{border-collapse:"
                  "collapse}td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%}"
                  "img{max-width:320px;image-rendering:pixelated}.err{color:#b00}.known{color:#a60}"
                  "figure{display:inline-block;margin:2px}figcaption{font-size:80%}</style>"
                  "</head><body>\n<h1>vtkshadow: shadows against ray tracers</h1>\n";
  h += "<p>Visibility per light (white = lit). Reference: POV-Ray; Cycles row = the check of "
       "the reference itself; eevee / eevee-best rows = Blender's rasterizer as a peer. Heat "
       "maps: blue = test too dark (false shadow), red = too bright (false light), grey = not "
       "valid. See docs/harness.md.</p>\n";
  if (plot)
    h += "<p><img src=\"wrong_pct.png\" style=\"max-width:100%\" alt=\"wrong_pct plot\"></p>\n";
  return h;
}

// --check failures, then the known failures with their reasons and state.
std::string CheckSection(const Options& opt, const CheckOutcome& check)
{
  std::string h;
  if (opt.check && !check.failures.empty())
  {
    h += "<h2 class=\"err\">--check regressions</h2><ul>";
    for (const auto& f : check.failures)
      h += "<li class=\"err\">" + HtmlEscape(f) + "</li>";
    h += "</ul>\n";
  }
  if (check.known.empty())
    return h;
  h += "<h2 id=\"known-failures\">Known failures</h2>\n<p>Rows known to be wrong, listed with "
       "their reason in known-failures.json instead of a limit; the check fails when one starts "
       "passing, so the list only shrinks.</p>\n<table><tr><th>scene</th><th>light</th>"
       "<th>test</th><th>reason</th><th>this run</th></tr>";
  for (const KnownFailure& k : check.known)
  {
    const std::string state = !k.seen ? "not run"
      : !k.worse.empty()              ? "GOT WORSE (" + k.worse + ")"
      : k.still_failing               ? "still failing (" + k.measured + ")"
                                      : "NOW PASSES (" + k.measured + "): remove the entry";
    h += "<tr class=\"known\"><td>" + HtmlEscape(k.scene) + "</td><td>" + std::to_string(k.light) +
      "</td><td>" + HtmlEscape(k.test) + "</td><td>" + HtmlEscape(k.reason) + "</td><td" +
      (k.seen && (!k.still_failing || !k.worse.empty()) ? " class=\"err\"" : "") + ">" +
      HtmlEscape(state) + "</td></tr>";
  }
  return h + "</table>\n";
}

std::string RowTable(const SceneResult& sr, int k)
{
  std::string h =
    "<table><tr><th>test</th><th>valid px</th><th>vis_mae</th><th>wrong_pct</th>"
    "<th>wrong_band_pct</th><th>edge_px</th><th>false_shadow_pct</th><th>false_light_pct</th>"
    "<th>wrong_of_shadow_pct</th><th>reflection_mae</th>" +
    std::string(sr.tinted ? "<th>colour_mae</th>" : "") + "<th>status</th><th>check</th></tr>";
  for (const Row& r : sr.rows)
  {
    if (r.light != k)
      continue;
    char buf[512];
    snprintf(buf, sizeof buf,
      "<td>%ld</td><td>%.4g</td><td>%.4g</td><td>%s</td><td>%.4g</td><td>%.4g</td><td>%.4g</td>"
      "<td>%s</td><td>%s</td>",
      r.m.valid_pixels, r.m.vis_mae, r.m.wrong_pct,
      std::isfinite(r.wrong_band_pct) ? Fmt(r.wrong_band_pct, "%.4g").c_str() : "", r.m.edge_px,
      r.m.false_shadow_pct, r.m.false_light_pct, Fmt(r.m.wrong_of_shadow_pct, "%.4g").c_str(),
      std::isfinite(r.reflection_mae) ? Fmt(r.reflection_mae, "%.4f").c_str() : "");
    const char* cls = r.check.rfind("FAILED", 0) == 0 ? " class=\"err\""
      : r.check.rfind("known failure", 0) == 0        ? " class=\"known\""
                                                      : "";
    // colour_mae: a column of tinted scenes only.
    const std::string colour = !sr.tinted ? ""
      : std::isfinite(r.colour_mae)       ? "<td>" + Fmt(r.colour_mae, "%.4f") + "</td>"
                                          : "<td></td>";
    h += std::string("<tr") + cls + "><td>" + HtmlEscape(r.test) + "</td>" + buf + colour + "<td>" +
      HtmlEscape(r.status) + "</td><td>" + HtmlEscape(r.check) + "</td></tr>";
  }
  return h + "</table>\n";
}

// The penumbra table and heat maps of light k, when the reference has a
// penumbra there (a light with a size).
std::string PenumbraSection(const SceneResult& sr, int k)
{
  std::string maps, rows;
  for (const Row& r : sr.rows)
  {
    if (r.light != k || r.pen.penumbra_pixels == 0)
      continue;
    if (!r.pen_heatmap.empty())
      maps += "<figure><img src=\"" + HtmlEscape(r.pen_heatmap) + "\"><figcaption>" +
        HtmlEscape(r.test) + " penumbra</figcaption></figure>";
    char buf[512];
    snprintf(buf, sizeof buf,
      "<td>%ld</td><td>%.4f</td><td>%+.4f</td><td>%.3g</td><td>%.3g</td><td>%.3g</td>"
      "<td>%.3g</td><td>%.3g</td><td>%.3g</td>",
      r.pen.penumbra_pixels, r.pen.pen_mae, r.pen.pen_bias, r.pen.leak_pct, r.pen.false_shadow_pct,
      r.pen.width_ratio, r.pen.contour_px[0], r.pen.contour_px[1], r.pen.contour_px[2]);
    rows += "<tr><td>" + HtmlEscape(r.test) + "</td>" + buf + "</tr>";
  }
  if (rows.empty())
    return "";
  return "<p>Penumbra (0.02 &lt; v_ref &lt; 0.98, dilated 1 px; heat map: blue too dark, red "
         "too bright, saturated at 0.25, the rest the reference in grey)</p><div>" +
    maps +
    "</div><table><tr><th>test</th><th>penumbra px</th><th>pen_mae</th><th>pen_bias</th>"
    "<th>leak %</th><th>false shadow %</th><th>width ratio</th><th>contour 0.1</th>"
    "<th>contour 0.5</th><th>contour 0.9</th></tr>" +
    rows + "</table>\n";
}

std::string LightSection(const Options& opt, const SceneResult& sr, int k)
{
  std::string h =
    "<h3>light " + std::to_string(k) + " (" + HtmlEscape(sr.light_types[k]) + ")</h3>\n<div>";
  std::vector<std::string> imgs{ "povray" };
  for (const std::string& b : BlenderRenderers())
    imgs.push_back(b);
  for (const auto& t : opt.techniques)
    imgs.push_back("vtk/" + t);
  const std::string lk = "light" + std::to_string(k);
  for (const auto& im : imgs)
  {
    const std::string rel = sr.entry.dir_id + "/" + im + "/" + lk + "_visibility.png";
    if (FileExists(opt.out + "/" + rel))
      h += "<figure><img src=\"" + HtmlEscape(rel) + "\"><figcaption>" + HtmlEscape(im) +
        "</figcaption></figure>";
  }
  h += "</div><div>";
  for (const Row& r : sr.rows)
    if (r.light == k && !r.heatmap.empty())
      h += "<figure><img src=\"" + HtmlEscape(r.heatmap) + "\"><figcaption>" + HtmlEscape(r.test) +
        " &minus; povray</figcaption></figure>";
  return h + "</div>\n" + RowTable(sr, k) + PenumbraSection(sr, k);
}

// Scenes with mirrors: the colour images (every light), the mirror's pixels
// and each test's heat map over them (reflection_mae in the tables below).
std::string MirrorSection(const Options& opt, const SceneResult& sr)
{
  if (sr.mirror_image.empty())
    return "";
  std::string h = "<h3>mirrors: colour, every light (reflection_mae against povray over the "
                  "mirror's pixels)</h3>\n<div>";
  std::vector<std::string> imgs{ "povray", "cycles" };
  for (const auto& t : opt.techniques)
    imgs.push_back("vtk/" + t);
  for (const auto& im : imgs)
  {
    const std::string rel = sr.entry.dir_id + "/" + im + "/color.png";
    if (FileExists(opt.out + "/" + rel))
      h += "<figure><img src=\"" + HtmlEscape(rel) + "\"><figcaption>" + HtmlEscape(im) +
        "</figcaption></figure>";
  }
  h += "<figure><img src=\"" + HtmlEscape(sr.mirror_image) +
    "\"><figcaption>mirror pixels (povray)</figcaption></figure></div><div>";
  std::set<std::string> shown;
  for (const Row& r : sr.rows)
    if (!r.mirror_heatmap.empty() && shown.insert(r.test).second)
      h += "<figure><img src=\"" + HtmlEscape(r.mirror_heatmap) + "\"><figcaption>" +
        HtmlEscape(r.test) + " &minus; povray, mirror, " + Fmt(r.reflection_mae, "%.4f") +
        "</figcaption></figure>";
  return h + "</div>\n";
}

} // namespace

bool WriteHtml(
  const Options& opt, const std::vector<SceneResult>& all, bool plot, const CheckOutcome& check)
{
  std::string h = Header(plot) + CheckSection(opt, check);
  h += "<h2>Scenes</h2><ul>";
  for (const SceneResult& sr : all)
    h += "<li><a href=\"#" + HtmlEscape(sr.entry.dir_id) + "\">" + HtmlEscape(sr.entry.id) +
      "</a>" + (sr.errors.empty() ? "" : " <span class=\"err\">(errors)</span>") + "</li>";
  h += "</ul>\n";
  for (const SceneResult& sr : all)
  {
    h += "<h2 id=\"" + HtmlEscape(sr.entry.dir_id) + "\">" + HtmlEscape(sr.entry.id) +
      "</h2>\n<p>" + HtmlEscape(sr.description) + " (" + std::to_string(sr.width) + "x" +
      std::to_string(sr.height) + ")</p>\n";
    for (const auto& err : sr.errors)
      h += "<p class=\"err\">" + HtmlEscape(err) + "</p>\n";
    h += MirrorSection(opt, sr);
    for (int k = 0; k < sr.lights; ++k)
      h += LightSection(opt, sr, k);
  }
  h += "<p>Machine-readable: <a href=\"results.csv\">results.csv</a>, "
       "<a href=\"results.json\">results.json</a>.</p></body></html>\n";
  std::string err;
  if (!WriteFileAtomic(opt.out + "/index.html", h, err))
  {
    Progress("ERROR writing index.html: " + err);
    return false;
  }
  return true;
}

} // namespace vsh_harness
