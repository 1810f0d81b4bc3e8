/* vsh_auto_general.c - the general candidates' choice and the thin-caster
 * measure (see vsh_auto_general.h). */
#include "vsh_auto_general.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int vsh_auto_pick_cheapest(const vsh_auto_candidate *candidates, int count,
                           double max_error_pct, int *met)
{
  if (met)
    *met = 0;
  if (!candidates || count <= 0)
    return -1;
  int best = -1, fallback = -1;
  for (int i = 0; i < count; ++i) {
    const vsh_auto_candidate *c = &candidates[i];
    if (!c->available || isnan(c->predicted_error_pct) || isnan(c->cost))
      continue;
    if (c->predicted_error_pct <= max_error_pct &&
        (best < 0 || c->cost < candidates[best].cost))
      best = i;
    if (fallback < 0 || c->predicted_error_pct < candidates[fallback].predicted_error_pct ||
        (c->predicted_error_pct == candidates[fallback].predicted_error_pct &&
         c->cost < candidates[fallback].cost))
      fallback = i;
  }
  if (best >= 0) {
    if (met)
      *met = 1;
    return best;
  }
  return fallback;
}

int vsh_auto_map_resolves(double thickness_px, double texel_px, double min_texels)
{
  if (!(texel_px > 0.0) || isnan(thickness_px) || !(min_texels >= 0.0))
    return 0;
  return thickness_px >= min_texels * texel_px;
}

unsigned int vsh_auto_light_mask(const int *techniques, int count, int technique)
{
  unsigned int mask = 0u;
  for (int l = 0; techniques && l < count && l < 32; ++l)
    mask |= (techniques[l] == technique ? 1u : 0u) << l;
  return mask;
}

double vsh_auto_thin_caster_error(double thickness_px, double texel_px, double edge_length_px,
                                  double pixels)
{
  if (!(pixels > 0.0) || isnan(edge_length_px))
    return INFINITY;
  if (vsh_auto_map_resolves(thickness_px, texel_px, 2.0))
    return 0.0;
  const double width = isfinite(thickness_px) ? fmax(thickness_px, 1.0) : 1.0;
  return 100.0 * 0.5 * fmax(edge_length_px, 0.0) * width / pixels;
}

/* ---- principal extents per component ------------------------------------ */

typedef struct component_sums {
  size_t n;
  double origin[3]; /* the first vertex: sums relative to it keep digits */
  double sum[3];
  double cov[6]; /* xx, xy, xz, yy, yz, zz (of positions - origin) */
} component_sums;

/* Eigenvectors of a symmetric 3x3 matrix (cyclic Jacobi), as rows of v. */
static void symmetric_eigenvectors(const double m[6], double v[3][3])
{
  double a[3][3] = {{m[0], m[1], m[2]}, {m[1], m[3], m[4]}, {m[2], m[4], m[5]}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-30 * diag || off == 0.0)
      break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0)
          continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        const double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) { /* columns p, q of a */
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) { /* rows p, q of a */
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) { /* eigenvector rows */
          const double vp = v[p][k], vq = v[q][k];
          v[p][k] = c * vp - s * vq;
          v[q][k] = s * vp + c * vq;
        }
      }
    }
  }
}

/* A component's principal axes (eigenvectors of its vertices' covariance)
 * and empty extents along them, to be grown by its vertices. */
static void principal_frame(const component_sums *s, double axes[3][3], double lo[3],
                            double hi[3])
{
  const double n = s->n > 0 ? (double)s->n : 1.0, *m = s->sum;
  const double cov[6] = {s->cov[0] - m[0] * m[0] / n, s->cov[1] - m[0] * m[1] / n,
                         s->cov[2] - m[0] * m[2] / n, s->cov[3] - m[1] * m[1] / n,
                         s->cov[4] - m[1] * m[2] / n, s->cov[5] - m[2] * m[2] / n};
  symmetric_eigenvectors(cov, axes);
  for (int k = 0; k < 3; ++k) {
    lo[k] = INFINITY;
    hi[k] = -INFINITY;
  }
}

static void sort3(double e[3])
{
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2 - i; ++j)
      if (e[j] > e[j + 1]) {
        const double t = e[j];
        e[j] = e[j + 1];
        e[j + 1] = t;
      }
}

static void accumulate(component_sums *sums, const double *positions, size_t vertex_count,
                       const unsigned int *component, size_t component_count)
{
  for (size_t v = 0; v < vertex_count; ++v) {
    const unsigned int c = component[v];
    if (c >= component_count)
      continue;
    component_sums *s = &sums[c];
    const double *p = positions + 3 * v;
    if (s->n == 0)
      memcpy(s->origin, p, sizeof s->origin);
    const double d[3] = {p[0] - s->origin[0], p[1] - s->origin[1], p[2] - s->origin[2]};
    for (int k = 0; k < 3; ++k)
      s->sum[k] += d[k];
    s->cov[0] += d[0] * d[0];
    s->cov[1] += d[0] * d[1];
    s->cov[2] += d[0] * d[2];
    s->cov[3] += d[1] * d[1];
    s->cov[4] += d[1] * d[2];
    s->cov[5] += d[2] * d[2];
    ++s->n;
  }
}

double vsh_mesh_thinnest_width(const double *positions, size_t vertex_count,
                               const unsigned int *component, size_t component_count)
{
  double thinnest = INFINITY;
  if (!positions || !component || component_count == 0 || vertex_count == 0)
    return thinnest;
  component_sums *sums = calloc(component_count, sizeof *sums);
  double (*axes)[3][3] = calloc(component_count, sizeof *axes);
  double (*lo)[3] = malloc(component_count * sizeof *lo);
  double (*hi)[3] = malloc(component_count * sizeof *hi);
  if (!sums || !axes || !lo || !hi)
    goto done;
  accumulate(sums, positions, vertex_count, component, component_count);
  for (size_t c = 0; c < component_count; ++c) {
    if (sums[c].n < 2)
      continue;
    principal_frame(&sums[c], axes[c], lo[c], hi[c]);
  }
  /* Extents along the axes, relative to each component's first vertex. */
  for (size_t v = 0; v < vertex_count; ++v) {
    const unsigned int c = component[v];
    if (c >= component_count || sums[c].n < 2)
      continue;
    const double *p = positions + 3 * v, *o = sums[c].origin;
    const double d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    for (int k = 0; k < 3; ++k) {
      const double x = axes[c][k][0] * d[0] + axes[c][k][1] * d[1] + axes[c][k][2] * d[2];
      lo[c][k] = fmin(lo[c][k], x);
      hi[c][k] = fmax(hi[c][k], x);
    }
  }
  for (size_t c = 0; c < component_count; ++c) {
    if (sums[c].n < 2)
      continue;
    double e[3] = {hi[c][0] - lo[c][0], hi[c][1] - lo[c][1], hi[c][2] - lo[c][2]};
    sort3(e);
    if (isfinite(e[1]))
      thinnest = fmin(thinnest, e[1]);
  }
done:
  free(sums);
  free(axes);
  free(lo);
  free(hi);
  return thinnest;
}

/* ---- tapered parts ------------------------------------------------------- */

/* Per component: the axis to slice along (largest extent) and the axis to
 * measure widths along (middle extent), with the slicing axis's start and
 * slice length. */
typedef struct taper_frame {
  double along[3], across[3];
  double start, step;
  int valid;
} taper_frame;

static void taper_frames(const double *positions, size_t vertex_count,
                         const unsigned int *component, size_t component_count,
                         const component_sums *sums, taper_frame *frames)
{
  double (*axes)[3][3] = calloc(component_count, sizeof *axes);
  double (*lo)[3] = malloc(component_count * sizeof *lo);
  double (*hi)[3] = malloc(component_count * sizeof *hi);
  if (!axes || !lo || !hi)
    goto done;
  for (size_t c = 0; c < component_count; ++c) {
    principal_frame(&sums[c], axes[c], lo[c], hi[c]);
  }
  for (size_t v = 0; v < vertex_count; ++v) {
    const unsigned int c = component[v];
    if (c >= component_count)
      continue;
    const double *p = positions + 3 * v, *o = sums[c].origin;
    for (int k = 0; k < 3; ++k) {
      const double x = axes[c][k][0] * (p[0] - o[0]) + axes[c][k][1] * (p[1] - o[1]) +
                       axes[c][k][2] * (p[2] - o[2]);
      lo[c][k] = fmin(lo[c][k], x);
      hi[c][k] = fmax(hi[c][k], x);
    }
  }
  for (size_t c = 0; c < component_count; ++c) {
    int order[3] = {0, 1, 2}; /* axes by extent, largest first */
    double e[3];
    for (int k = 0; k < 3; ++k)
      e[k] = hi[c][k] - lo[c][k];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2 - i; ++j)
        if (e[order[j]] < e[order[j + 1]]) {
          const int t = order[j];
          order[j] = order[j + 1];
          order[j + 1] = t;
        }
    taper_frame *f = &frames[c];
    f->valid = sums[c].n >= 2 && e[order[0]] > 0.0 && isfinite(e[order[0]]);
    memcpy(f->along, axes[c][order[0]], sizeof f->along);
    memcpy(f->across, axes[c][order[1]], sizeof f->across);
    f->start = lo[c][order[0]];
    f->step = e[order[0]] / VSH_MESH_TAPER_SLICES;
  }
done:
  free(axes);
  free(lo);
  free(hi);
}

static double dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Where edge a-b crosses the centre planes of component c's slices: widen
 * those slices' [lo, hi] across. */
static void taper_edge(const double *pa, const double *pb, const double *origin,
                       const taper_frame *f, double *lo, double *hi)
{
  const double da[3] = {pa[0] - origin[0], pa[1] - origin[1], pa[2] - origin[2]};
  const double db[3] = {pb[0] - origin[0], pb[1] - origin[1], pb[2] - origin[2]};
  const double xa = dot3(f->along, da) - f->start, xb = dot3(f->along, db) - f->start;
  const double ma = dot3(f->across, da), mb = dot3(f->across, db);
  const double x0 = fmin(xa, xb) / f->step - 0.5, x1 = fmax(xa, xb) / f->step - 0.5;
  const int k0 = (int)fmax(ceil(x0), 0.0), k1 = (int)fmin(floor(x1), VSH_MESH_TAPER_SLICES - 1);
  for (int k = k0; k <= k1; ++k) {
    const double xc = (k + 0.5) * f->step;
    const double t = xb != xa ? (xc - xa) / (xb - xa) : 0.0;
    const double m = ma + t * (mb - ma);
    lo[k] = fmin(lo[k], m);
    hi[k] = fmax(hi[k], m);
    if (xb == xa) { /* the edge lies in the plane: both ends */
      lo[k] = fmin(lo[k], mb);
      hi[k] = fmax(hi[k], mb);
    }
  }
}

size_t vsh_mesh_taper_profile(const double *positions, size_t vertex_count,
                              const unsigned int *triangles, size_t triangle_count,
                              const unsigned int *component, size_t component_count,
                              double *widths, double *lengths)
{
  enum { S = VSH_MESH_TAPER_SLICES };
  if (!positions || !component || !widths || !lengths || component_count == 0 ||
      (triangle_count > 0 && !triangles))
    return 0;
  for (size_t i = 0; i < 3 * triangle_count; ++i)
    if (triangles[i] >= vertex_count)
      return 0;
  const size_t count = component_count * S;
  component_sums *sums = calloc(component_count, sizeof *sums);
  taper_frame *frames = calloc(component_count, sizeof *frames);
  double *lo = malloc(count * sizeof *lo), *hi = malloc(count * sizeof *hi);
  size_t written = 0;
  if (!sums || !frames || !lo || !hi)
    goto done;
  accumulate(sums, positions, vertex_count, component, component_count);
  taper_frames(positions, vertex_count, component, component_count, sums, frames);
  for (size_t i = 0; i < count; ++i) {
    lo[i] = INFINITY;
    hi[i] = -INFINITY;
  }
  for (size_t t = 0; t < triangle_count; ++t) {
    const unsigned int *tri = triangles + 3 * t, c = component[tri[0]];
    if (c >= component_count || !frames[c].valid)
      continue;
    for (int e = 0; e < 3; ++e)
      taper_edge(positions + 3 * tri[e], positions + 3 * tri[(e + 1) % 3], sums[c].origin,
                 &frames[c], lo + c * S, hi + c * S);
  }
  for (size_t i = 0; i < count; ++i) {
    const taper_frame *f = &frames[i / S];
    widths[i] = f->valid && hi[i] >= lo[i] ? hi[i] - lo[i] : 0.0;
    lengths[i] = f->valid ? f->step : 0.0;
  }
  written = count;
done:
  free(sums);
  free(frames);
  free(lo);
  free(hi);
  return written;
}

double vsh_auto_taper_error(const double *widths, const double *lengths, size_t count,
                            double px_per_unit, double texel_px, double min_texels,
                            double stretch, double pixels)
{
  if (!(pixels > 0.0) || !(texel_px > 0.0) || !(px_per_unit > 0.0) || !(stretch >= 1.0) ||
      !isfinite(px_per_unit) || !(min_texels >= 0.0))
    return INFINITY;
  if (!widths || !lengths || count == 0)
    return 0.0;
  const double lost = min_texels * texel_px;
  double area = 0.0;
  for (size_t i = 0; i < count; ++i) {
    const double w = widths[i] * px_per_unit;
    if (w > 0.0 && w < lost && isfinite(lengths[i]))
      area += w * lengths[i] * px_per_unit;
  }
  return 100.0 * area * stretch / pixels;
}

/* ---- a map's outline floor ----------------------------------------------- */

double vsh_auto_map_outline_error(double outline_px, double stretch, double pixels)
{
  if (!(pixels > 0.0) || !isfinite(pixels) || !(outline_px >= 0.0) || !isfinite(outline_px) ||
      !(stretch >= 1.0) || !isfinite(stretch))
    return INFINITY;
  return 100.0 * VSH_AUTO_MAP_OUTLINE_FLOOR * outline_px * stretch / pixels;
}

double vsh_auto_volume_floor_error(double outline_px, double zpass_open_quads,
                                   double zfail_open_quads, double pixels)
{
  double wrong_px;
  if (!(outline_px >= 0.0) || !(zpass_open_quads >= 0.0) || !(zfail_open_quads >= 0.0) ||
      !(pixels > 0.0) || !isfinite(pixels))
    return INFINITY;
  if (outline_px == 0.0 && zpass_open_quads == 0.0 && zfail_open_quads == 0.0)
    return 0.0;
  wrong_px = VSH_AUTO_VOLUME_FLOOR_PX + VSH_AUTO_VOLUME_OUTLINE_FLOOR * outline_px +
             (VSH_AUTO_VOLUME_OPEN_QUAD * zpass_open_quads +
              VSH_AUTO_VOLUME_OPEN_QUAD_ZFAIL * zfail_open_quads) *
               (pixels / VSH_AUTO_VOLUME_REFERENCE_PIXELS);
  return 100.0 * wrong_px / pixels;
}

/* ---- thin impostor casters ---------------------------------------------- */

static int thin_input_ok(double thin_outline_px, double pixels)
{
  return pixels > 0.0 && isfinite(pixels) && thin_outline_px >= 0.0 && isfinite(thin_outline_px);
}

double vsh_auto_thin_floor_error(double point_outline_px, double line_outline_px, double pixels)
{
  if (!thin_input_ok(point_outline_px, pixels) || !thin_input_ok(line_outline_px, pixels))
    return INFINITY;
  return 100.0 *
         (VSH_AUTO_THIN_POINT_FLOOR * point_outline_px + VSH_AUTO_THIN_LINE_FLOOR * line_outline_px) /
         pixels;
}

double vsh_auto_thin_map_error(double thin_outline_px, double texel_px, double pixels)
{
  if (!thin_input_ok(thin_outline_px, pixels) || !(texel_px > 0.0) || isnan(texel_px))
    return INFINITY;
  if (thin_outline_px == 0.0)
    return 0.0;
  return 100.0 * VSH_AUTO_THIN_MAP_PER_TEXEL * texel_px * thin_outline_px / pixels;
}

double vsh_auto_thin_texel_target(double budget_pct, double thin_outline_px, double pixels)
{
  if (!thin_input_ok(thin_outline_px, pixels) || isnan(budget_pct))
    return 0.0;
  if (thin_outline_px == 0.0)
    return INFINITY;
  if (!(budget_pct > 0.0))
    return 0.0;
  return budget_pct / 100.0 * pixels / (VSH_AUTO_THIN_MAP_PER_TEXEL * thin_outline_px);
}

double vsh_auto_thin_frame_texel(double texel_px, double max_wrong_pct,
                                 const double *point_outlines, const double *line_outlines,
                                 int count, double pixels)
{
  if (!(texel_px > 0.0) || !point_outlines || !line_outlines || isnan(max_wrong_pct))
    return texel_px;
  double t = texel_px;
  for (int l = 0; l < count; ++l) {
    const double outline = point_outlines[l] + line_outlines[l];
    if (!(outline > 0.0))
      continue;
    const double budget =
        max_wrong_pct - vsh_auto_thin_floor_error(point_outlines[l], line_outlines[l], pixels);
    const double thin = vsh_auto_thin_texel_target(budget, outline, pixels);
    if (thin >= VSH_AUTO_THIN_MIN_TEXEL_PX)
      t = fmin(t, thin);
  }
  return t;
}
