/* vsh_impostor_proxy.c - sphere and tube proxies (see the header). */
#include "vsh_impostor_proxy.h"

#include <math.h>
#include <string.h>

#define VSH_PI 3.14159265358979323846

/* The icosahedron (vertices on the unit sphere after normalizing), wound
 * counter-clockwise seen from outside. */
static const double ico_vertices[12][3] = {
  { -1, 1.6180339887498949, 0 }, { 1, 1.6180339887498949, 0 },
  { -1, -1.6180339887498949, 0 }, { 1, -1.6180339887498949, 0 },
  { 0, -1, 1.6180339887498949 }, { 0, 1, 1.6180339887498949 },
  { 0, -1, -1.6180339887498949 }, { 0, 1, -1.6180339887498949 },
  { 1.6180339887498949, 0, -1 }, { 1.6180339887498949, 0, 1 },
  { -1.6180339887498949, 0, -1 }, { -1.6180339887498949, 0, 1 } };
static const uint32_t ico_faces[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
  { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 },
  { 3, 9, 4 }, { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 },
  { 6, 2, 10 }, { 8, 6, 7 }, { 9, 8, 1 } };

static void normalize_into(const double v[3], double *out)
{
  const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; ++k) {
    out[k] = v[k] / n;
  }
}

/* The index of edge (a, b)'s midpoint vertex: made (on the unit sphere)
 * the first time the edge is met. */
static uint32_t midpoint(double *vertices, uint32_t *count, uint32_t edges[][3], int *edge_count,
                         uint32_t a, uint32_t b)
{
  const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
  for (int e = 0; e < *edge_count; ++e) {
    if (edges[e][0] == lo && edges[e][1] == hi) {
      return edges[e][2];
    }
  }
  double m[3];
  for (int k = 0; k < 3; ++k) {
    m[k] = vertices[3 * a + k] + vertices[3 * b + k];
  }
  normalize_into(m, vertices + 3 * *count);
  edges[*edge_count][0] = lo;
  edges[*edge_count][1] = hi;
  edges[*edge_count][2] = *count;
  ++*edge_count;
  return (*count)++;
}

static double triangle_area(const double *p, const double *q, const double *r)
{
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = q[k] - p[k];
    v[k] = r[k] - p[k];
  }
  const double c[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                        u[0] * v[1] - u[1] * v[0] };
  return 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

void vsh_proxy_shapes_init(vsh_proxy_shapes *shapes)
{
  memset(shapes, 0, sizeof(*shapes));
  uint32_t count = 12;
  for (uint32_t i = 0; i < 12; ++i) {
    normalize_into(ico_vertices[i], shapes->sphere + 3 * i);
  }
  /* Each face into four: its corners' triangles and the middle one, all
   * wound as the face is. */
  uint32_t edges[30][3];
  int edge_count = 0;
  for (int f = 0; f < 20; ++f) {
    const uint32_t a = ico_faces[f][0], b = ico_faces[f][1], c = ico_faces[f][2];
    const uint32_t ab = midpoint(shapes->sphere, &count, edges, &edge_count, a, b);
    const uint32_t bc = midpoint(shapes->sphere, &count, edges, &edge_count, b, c);
    const uint32_t ca = midpoint(shapes->sphere, &count, edges, &edge_count, c, a);
    const uint32_t quad[4][3] = { { a, ab, ca }, { b, bc, ab }, { c, ca, bc }, { ab, bc, ca } };
    memcpy(shapes->sphere_triangles + 12 * f, quad, sizeof(quad));
  }
  double area = 0.0;
  for (int t = 0; t < VSH_PROXY_SPHERE_TRIANGLES; ++t) {
    const uint32_t *tri = shapes->sphere_triangles + 3 * t;
    area += triangle_area(shapes->sphere + 3 * tri[0], shapes->sphere + 3 * tri[1],
                          shapes->sphere + 3 * tri[2]);
  }
  /* Cauchy: mean projected area = area / 4, the unit disc's pi. */
  shapes->sphere_scale = sqrt(4.0 * VSH_PI / area);
  for (int i = 0; i < 3 * VSH_PROXY_SPHERE_VERTICES; ++i) {
    shapes->sphere[i] *= shapes->sphere_scale;
  }
  /* The polygon's mean width (perimeter / pi) equals the circle's: 2. */
  const int n = VSH_PROXY_TUBE_SIDES;
  shapes->tube_scale = VSH_PI / (n * sin(VSH_PI / n));
  for (int k = 0; k < n; ++k) {
    shapes->ring[2 * k] = shapes->tube_scale * cos(2.0 * VSH_PI * k / n);
    shapes->ring[2 * k + 1] = shapes->tube_scale * sin(2.0 * VSH_PI * k / n);
  }
}

void vsh_proxy_sphere(const vsh_proxy_shapes *shapes, const double centre[3], double radius,
                      double *vertices, uint32_t *triangles, uint32_t base)
{
  for (int i = 0; i < VSH_PROXY_SPHERE_VERTICES; ++i) {
    for (int k = 0; k < 3; ++k) {
      vertices[3 * i + k] = centre[k] + radius * shapes->sphere[3 * i + k];
    }
  }
  for (int i = 0; i < 3 * VSH_PROXY_SPHERE_TRIANGLES; ++i) {
    triangles[i] = base + shapes->sphere_triangles[i];
  }
}

/* u, v: a unit frame perpendicular to unit d with u x v = d. */
static void perpendicular_frame(const double d[3], double u[3], double v[3])
{
  /* Crossed with the axis d is least along: never nearly parallel. */
  const double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
  const double axis[3] = { ax <= ay && ax <= az ? 1.0 : 0.0,
                           ay < ax && ay <= az ? 1.0 : 0.0, az < ax && az < ay ? 1.0 : 0.0 };
  const double c[3] = { d[1] * axis[2] - d[2] * axis[1], d[2] * axis[0] - d[0] * axis[2],
                        d[0] * axis[1] - d[1] * axis[0] };
  normalize_into(c, u);
  v[0] = d[1] * u[2] - d[2] * u[1];
  v[1] = d[2] * u[0] - d[0] * u[2];
  v[2] = d[0] * u[1] - d[1] * u[0];
}

int vsh_proxy_tube(const vsh_proxy_shapes *shapes, const double a[3], double ra, const double b[3],
                   double rb, int turn, double *vertices, uint32_t *triangles, uint32_t base)
{
  double d[3], u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = b[k] - a[k];
  }
  const double length = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(length > 0.0) || !isfinite(length) || !isfinite(ra) || !isfinite(rb)) {
    return 0;
  }
  for (int k = 0; k < 3; ++k) {
    d[k] /= length;
  }
  perpendicular_frame(d, u, v);
  const int n = VSH_PROXY_TUBE_SIDES;
  const double half = (turn & 1) ? VSH_PI / n : 0.0;
  const double c = cos(half), s = sin(half);
  for (int i = 0; i < n; ++i) {
    /* The ring's side i turned by `half`. */
    const double x = c * shapes->ring[2 * i] - s * shapes->ring[2 * i + 1];
    const double y = s * shapes->ring[2 * i] + c * shapes->ring[2 * i + 1];
    for (int k = 0; k < 3; ++k) {
      const double radial = x * u[k] + y * v[k];
      vertices[3 * i + k] = a[k] + ra * radial;
      vertices[3 * (n + i) + k] = b[k] + rb * radial;
    }
  }
  /* Sides: ring a is 0..n-1, ring b n..2n-1; counter-clockwise about d, so
   * (a_i, a_i+1, b_i) faces outwards. */
  uint32_t *t = triangles;
  for (int i = 0; i < n; ++i) {
    const uint32_t a0 = base + (uint32_t)i, a1 = base + (uint32_t)((i + 1) % n);
    const uint32_t b0 = a0 + (uint32_t)n, b1 = a1 + (uint32_t)n;
    const uint32_t quad[6] = { a0, a1, b0, a1, b1, b0 };
    memcpy(t, quad, sizeof(quad));
    t += 6;
  }
  /* Caps: b's faces along d, a's against it. */
  for (int i = 1; i + 1 < n; ++i) {
    const uint32_t caps[6] = { base + (uint32_t)n, base + (uint32_t)(n + i),
                               base + (uint32_t)(n + i + 1), base, base + (uint32_t)(i + 1),
                               base + (uint32_t)i };
    memcpy(t, caps, sizeof(caps));
    t += 6;
  }
  return 1;
}

/* The eye's x and y axes in world coordinates (the view's first two rows),
 * unit length; 0 when degenerate. */
static int eye_axes(const double view[16], double right[3], double up[3])
{
  normalize_into(view, right);
  normalize_into(view + 4, up);
  /* A zero row normalizes to NaNs. */
  return isfinite(right[0] + right[1] + right[2] + up[0] + up[1] + up[2]);
}

/* The quad from p (half-width sp) to q (sq) across unit y: (p - y, q - y,
 * q + y, p + y), counter-clockwise seen from the camera when y is the
 * direction p -> q on screen turned a quarter counter-clockwise. */
static void quad_corners(const double p[3], const double q[3], double sp, double sq,
                         const double y[3], double corners[12])
{
  for (int k = 0; k < 3; ++k) {
    corners[k] = p[k] - sp * y[k];
    corners[3 + k] = q[k] - sq * y[k];
    corners[6 + k] = q[k] + sq * y[k];
    corners[9 + k] = p[k] + sp * y[k];
  }
}

int vsh_flat_square(const double view[16], const double centre[3], double half,
                    double corners[12])
{
  double right[3], up[3];
  if (!(half > 0.0) || !isfinite(half) || !isfinite(centre[0] + centre[1] + centre[2]) ||
      !eye_axes(view, right, up)) {
    return 0;
  }
  /* The square about the centre: its left and right edges' midpoints are
   * centre -/+ half * right, each spanning +-half * up. */
  double left[3], rightmid[3];
  for (int k = 0; k < 3; ++k) {
    left[k] = centre[k] - half * right[k];
    rightmid[k] = centre[k] + half * right[k];
  }
  quad_corners(left, rightmid, half, half, up, corners);
  return 1;
}

int vsh_flat_band(const double projection[16], const double view[16], const double a[3], double ra,
                  const double b[3], double rb, double corners[12])
{
  double right[3], up[3], ea[4] = { 0, 0, 0, 1 }, d[4] = { 0, 0, 0, 0 };
  if (!(ra > 0.0) || !(rb > 0.0) || !isfinite(ra) || !isfinite(rb) ||
      !isfinite(a[0] + a[1] + a[2] + b[0] + b[1] + b[2]) || !eye_axes(view, right, up)) {
    return 0;
  }
  for (int r = 0; r < 3; ++r) {
    ea[r] = view[4 * r] * a[0] + view[4 * r + 1] * a[1] + view[4 * r + 2] * a[2] + view[4 * r + 3];
    d[r] = view[4 * r] * (b[0] - a[0]) + view[4 * r + 1] * (b[1] - a[1]) +
           view[4 * r + 2] * (b[2] - a[2]);
  }
  /* On screen x / w and y / w (square pixels); along the segment their
   * derivative is (d.xy w - a.xy dw) / w^2, w and dw from the projection's
   * last row. */
  double w = 0.0, dw = 0.0;
  for (int c = 0; c < 4; ++c) {
    w += projection[12 + c] * ea[c];
    dw += projection[12 + c] * d[c];
  }
  const double sx = d[0] * w - ea[0] * dw, sy = d[1] * w - ea[1] * dw;
  const double length = sqrt(sx * sx + sy * sy);
  if (!(length > 0.0) || !isfinite(length)) {
    return 0;
  }
  /* Across the screen direction (turned a quarter counter-clockwise), in
   * world coordinates. */
  double across[3];
  for (int k = 0; k < 3; ++k) {
    across[k] = (-sy * right[k] + sx * up[k]) / length;
  }
  quad_corners(a, b, ra, rb, across, corners);
  return 1;
}
