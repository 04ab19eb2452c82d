/*
 * svg_plot.c - see svg_plot.h. Items are copied into the figure when
 * added; the data range, ticks and pixel mapping are resolved only when the
 * document is written, so items can be added in any order.
 */
#include "svg_plot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef enum item_kind {
  ITEM_LINE,
  ITEM_SCATTER,
  ITEM_COLORED,
  ITEM_MARKER,
  ITEM_TEXT,
  ITEM_LEGEND_ONLY
} item_kind;

typedef struct item {
  item_kind kind;
  double* x;
  double* y;
  unsigned* index; /* ITEM_COLORED: colour index per segment */
  size_t n;
  char color[32];
  char** palette; /* ITEM_COLORED */
  unsigned palette_count;
  double width;  /* line width or marker radius */
  int dashed;
  svp_marker_shape shape;
  char* label; /* legend entry (line/scatter/legend-only) */
  char* text;  /* marker / text item */
} item;

struct svp_figure {
  double width, height;
  char* title;
  char* xlabel;
  char* ylabel;
  int fixed_range;
  double xmin, xmax, ymin, ymax;
  int equal_aspect;
  int y_down;
  int x_left;
  item* items;
  size_t item_count, item_capacity;
};

/* Margins around the plot area, pixels. */
#define MARGIN_LEFT 64.0
#define MARGIN_RIGHT 16.0
#define MARGIN_TOP 34.0
#define MARGIN_BOTTOM 48.0

static char* dup_string(const char* s) {
  size_t n;
  char* d;
  if (!s) return NULL;
  n = strlen(s) + 1;
  d = (char*)malloc(n);
  if (d) memcpy(d, s, n);
  return d;
}

static void copy_color(char* dst, const char* color) {
  if (!color || !color[0]) color = "black";
  strncpy(dst, color, 31);
  dst[31] = '\0';
}

svp_figure* svp_create(double width, double height, const char* title) {
  svp_figure* fig;
  if (!(width >= 100.0 && height >= 100.0 && width < 1e5 && height < 1e5))
    return NULL;
  fig = (svp_figure*)calloc(1, sizeof(*fig));
  if (!fig) return NULL;
  fig->width = width;
  fig->height = height;
  if (title) {
    fig->title = dup_string(title);
    if (!fig->title) {
      free(fig);
      return NULL;
    }
  }
  return fig;
}

static void free_item(item* it) {
  unsigned i;
  free(it->x);
  free(it->y);
  free(it->index);
  if (it->palette) {
    for (i = 0; i < it->palette_count; ++i) free(it->palette[i]);
    free(it->palette);
  }
  free(it->label);
  free(it->text);
}

void svp_destroy(svp_figure* fig) {
  size_t i;
  if (!fig) return;
  for (i = 0; i < fig->item_count; ++i) free_item(&fig->items[i]);
  free(fig->items);
  free(fig->title);
  free(fig->xlabel);
  free(fig->ylabel);
  free(fig);
}

int svp_set_labels(svp_figure* fig, const char* xlabel, const char* ylabel) {
  char *xl = NULL, *yl = NULL;
  if (!fig) return -1;
  if (xlabel && !(xl = dup_string(xlabel))) return -1;
  if (ylabel && !(yl = dup_string(ylabel))) {
    free(xl);
    return -1;
  }
  free(fig->xlabel);
  free(fig->ylabel);
  fig->xlabel = xl;
  fig->ylabel = yl;
  return 0;
}

int svp_set_range(svp_figure* fig, double xmin, double xmax, double ymin,
                  double ymax) {
  if (!fig || !isfinite(xmin) || !isfinite(xmax) || !isfinite(ymin) ||
      !isfinite(ymax) || !(xmax > xmin) || !(ymax > ymin))
    return -1;
  fig->fixed_range = 1;
  fig->xmin = xmin;
  fig->xmax = xmax;
  fig->ymin = ymin;
  fig->ymax = ymax;
  return 0;
}

int svp_set_equal_aspect(svp_figure* fig, int on) {
  if (!fig) return -1;
  fig->equal_aspect = on != 0;
  return 0;
}

int svp_set_y_down(svp_figure* fig, int on) {
  if (!fig) return -1;
  fig->y_down = on != 0;
  return 0;
}

int svp_set_x_left(svp_figure* fig, int on) {
  if (!fig) return -1;
  fig->x_left = on != 0;
  return 0;
}

/* Appends a zeroed item; NULL when out of memory. */
static item* push_item(svp_figure* fig, item_kind kind) {
  item* it;
  if (fig->item_count == fig->item_capacity) {
    size_t cap = fig->item_capacity ? fig->item_capacity * 2 : 16;
    item* grown = (item*)realloc(fig->items, cap * sizeof(item));
    if (!grown) return NULL;
    fig->items = grown;
    fig->item_capacity = cap;
  }
  it = &fig->items[fig->item_count];
  memset(it, 0, sizeof(*it));
  it->kind = kind;
  return it;
}

/* Copies the coordinates of a pushed item; on failure pops it. */
static int fill_points(svp_figure* fig, item* it, const double* x,
                       const double* y, size_t n) {
  if (n) {
    it->x = (double*)malloc(n * sizeof(double));
    it->y = (double*)malloc(n * sizeof(double));
    if (!it->x || !it->y) {
      free_item(it);
      return -1;
    }
    memcpy(it->x, x, n * sizeof(double));
    memcpy(it->y, y, n * sizeof(double));
  }
  it->n = n;
  fig->item_count++;
  return 0;
}

int svp_line(svp_figure* fig, const double* x, const double* y, size_t n,
             const char* color, double width, int dashed, const char* label) {
  item* it;
  if (!fig || (n && (!x || !y)) || !(width > 0.0 && width < 100.0))
    return -1;
  if (!(it = push_item(fig, ITEM_LINE))) return -1;
  copy_color(it->color, color);
  it->width = width;
  it->dashed = dashed != 0;
  if (label && !(it->label = dup_string(label))) return -1;
  return fill_points(fig, it, x, y, n);
}

int svp_scatter(svp_figure* fig, const double* x, const double* y, size_t n,
                svp_marker_shape shape, const char* color, double radius,
                const char* label) {
  item* it;
  if (!fig || (n && (!x || !y)) || !(radius > 0.0 && radius < 100.0) ||
      (unsigned)shape > SVP_CROSS)
    return -1;
  if (!(it = push_item(fig, ITEM_SCATTER))) return -1;
  copy_color(it->color, color);
  it->width = radius;
  it->shape = shape;
  if (label && !(it->label = dup_string(label))) return -1;
  return fill_points(fig, it, x, y, n);
}

int svp_colored_line(svp_figure* fig, const double* x, const double* y,
                     size_t n, const unsigned* index,
                     const char* const* palette, unsigned palette_count,
                     double width) {
  item* it;
  size_t i;
  unsigned p;
  if (!fig || (n && (!x || !y || !index)) || !palette || !palette_count ||
      palette_count > 256 || !(width > 0.0 && width < 100.0))
    return -1;
  for (i = 0; i + 1 < n; ++i)
    if (index[i] >= palette_count) return -1;
  if (!(it = push_item(fig, ITEM_COLORED))) return -1;
  it->width = width;
  it->palette = (char**)calloc(palette_count, sizeof(char*));
  if (!it->palette) return -1;
  it->palette_count = palette_count;
  for (p = 0; p < palette_count; ++p)
    if (!(it->palette[p] = dup_string(palette[p] ? palette[p] : "black"))) {
      free_item(it);
      return -1;
    }
  if (n > 1) {
    it->index = (unsigned*)malloc((n - 1) * sizeof(unsigned));
    if (!it->index) {
      free_item(it);
      return -1;
    }
    memcpy(it->index, index, (n - 1) * sizeof(unsigned));
  }
  return fill_points(fig, it, x, y, n);
}

int svp_marker(svp_figure* fig, double x, double y, svp_marker_shape shape,
               const char* color, double radius, const char* text) {
  item* it;
  if (!fig || !(radius > 0.0 && radius < 100.0) ||
      (unsigned)shape > SVP_CROSS)
    return -1;
  if (!(it = push_item(fig, ITEM_MARKER))) return -1;
  copy_color(it->color, color);
  it->width = radius;
  it->shape = shape;
  if (text && !(it->text = dup_string(text))) return -1;
  return fill_points(fig, it, &x, &y, 1);
}

int svp_text(svp_figure* fig, double x, double y, const char* text,
             const char* color) {
  item* it;
  if (!fig || !text) return -1;
  if (!(it = push_item(fig, ITEM_TEXT))) return -1;
  copy_color(it->color, color);
  if (!(it->text = dup_string(text))) return -1;
  return fill_points(fig, it, &x, &y, 1);
}

int svp_legend_entry(svp_figure* fig, const char* label, const char* color,
                     int kind, svp_marker_shape shape) {
  item* it;
  if (!fig || !label || (unsigned)shape > SVP_CROSS) return -1;
  if (!(it = push_item(fig, ITEM_LEGEND_ONLY))) return -1;
  copy_color(it->color, color);
  it->shape = shape;
  it->dashed = kind; /* reused: 0 line swatch, 1 marker swatch */
  it->width = kind ? 4.0 : 2.5;
  if (!(it->label = dup_string(label))) return -1;
  fig->item_count++;
  return 0;
}

/* ---- ticks and text --------------------------------------------------- */

size_t svp_nice_ticks(double lo, double hi, size_t max_ticks,
                      double* out_first, double* out_step) {
  static const double mult[3] = {1.0, 2.0, 5.0};
  double span, p10, step = 0.0, first = 0.0;
  size_t count = 0;
  int e, k;
  if (!out_first || !out_step || !isfinite(lo) || !isfinite(hi) ||
      !(hi > lo) || max_ticks < 2)
    return 0;
  span = hi - lo;
  /* The smallest 1-2-5 step giving at most max_ticks ticks in range. */
  e = (int)floor(log10(span / (double)max_ticks)) - 1;
  for (; e < 400; ++e) {
    p10 = pow(10.0, (double)e);
    for (k = 0; k < 3; ++k) {
      step = mult[k] * p10;
      first = ceil(lo / step - 1e-9) * step;
      count = (size_t)floor((hi - first) / step + 1e-9) + 1;
      if (count <= max_ticks) goto done;
    }
  }
  return 0;
done:
  if (fabs(first) < step * 1e-9) first = 0.0; /* no "-0" */
  *out_first = first;
  *out_step = step;
  return count;
}

void svp_escape(const char* text, char* buf, size_t size) {
  size_t o = 0;
  const char* rep;
  if (!buf || !size) return;
  if (!text) text = "";
  for (; *text; ++text) {
    char one[2] = {0, 0};
    switch (*text) {
      case '&': rep = "&amp;"; break;
      case '<': rep = "&lt;"; break;
      case '>': rep = "&gt;"; break;
      case '"': rep = "&quot;"; break;
      default:
        /* Control characters are not allowed in XML 1.0 text. */
        one[0] = ((unsigned char)*text < 0x20) ? ' ' : *text;
        rep = one;
    }
    if (o + strlen(rep) + 1 > size) break;
    memcpy(buf + o, rep, strlen(rep));
    o += strlen(rep);
  }
  buf[o] = '\0';
}

/* Tick label without trailing zeros, e.g. 0.5, 10, -2.25, 1e+06. */
static void format_tick(double v, double step, char* buf, size_t size) {
  int decimals = 0;
  double s = step;
  while (decimals < 8 && fabs(s - floor(s + 0.5)) > 1e-9 * (fabs(s) + 1)) {
    s *= 10.0;
    decimals++;
  }
  if (fabs(v) >= 1e6 || (fabs(v) > 0 && fabs(v) < 1e-4))
    snprintf(buf, size, "%g", v);
  else
    snprintf(buf, size, "%.*f", decimals, v);
}

/* ---- writing ------------------------------------------------------------ */

typedef struct mapping {
  double x0, y0, w, h; /* plot area in pixels */
  double xmin, xmax, ymin, ymax;
  int y_down;
  int x_left;
} mapping;

static double map_x(const mapping* m, double x) {
  double t = (x - m->xmin) / (m->xmax - m->xmin);
  return m->x_left ? m->x0 + m->w - t * m->w : m->x0 + t * m->w;
}
static double map_y(const mapping* m, double y) {
  double t = (y - m->ymin) / (m->ymax - m->ymin);
  return m->y_down ? m->y0 + t * m->h : m->y0 + m->h - t * m->h;
}

static void grow_range(double v, double* lo, double* hi) {
  if (!isfinite(v)) return;
  if (v < *lo) *lo = v;
  if (v > *hi) *hi = v;
}

static void resolve_range(const svp_figure* fig, mapping* m) {
  double xl = INFINITY, xh = -INFINITY, yl = INFINITY, yh = -INFINITY;
  size_t i, j;
  if (fig->fixed_range) {
    xl = fig->xmin;
    xh = fig->xmax;
    yl = fig->ymin;
    yh = fig->ymax;
  } else {
    for (i = 0; i < fig->item_count; ++i) {
      const item* it = &fig->items[i];
      if (it->kind == ITEM_LEGEND_ONLY) continue;
      for (j = 0; j < it->n; ++j) {
        if (!isfinite(it->x[j]) || !isfinite(it->y[j])) continue;
        grow_range(it->x[j], &xl, &xh);
        grow_range(it->y[j], &yl, &yh);
      }
    }
    if (!(xh >= xl)) xl = 0.0, xh = 1.0;
    if (!(yh >= yl)) yl = 0.0, yh = 1.0;
    if (xh - xl < 1e-12) xl -= 0.5, xh += 0.5;
    if (yh - yl < 1e-12) yl -= 0.5, yh += 0.5;
    {
      double px = 0.04 * (xh - xl), py = 0.04 * (yh - yl);
      xl -= px;
      xh += px;
      yl -= py;
      yh += py;
    }
  }
  m->x0 = MARGIN_LEFT;
  m->y0 = MARGIN_TOP;
  m->w = fig->width - MARGIN_LEFT - MARGIN_RIGHT;
  m->h = fig->height - MARGIN_TOP - MARGIN_BOTTOM;
  if (fig->equal_aspect) {
    /* Units per pixel equal on both axes: widen the tighter axis. */
    double ux = (xh - xl) / m->w, uy = (yh - yl) / m->h;
    if (ux > uy) {
      double c = 0.5 * (yl + yh), half = 0.5 * ux * m->h;
      yl = c - half;
      yh = c + half;
    } else {
      double c = 0.5 * (xl + xh), half = 0.5 * uy * m->w;
      xl = c - half;
      xh = c + half;
    }
  }
  m->xmin = xl;
  m->xmax = xh;
  m->ymin = yl;
  m->ymax = yh;
  m->y_down = fig->y_down;
  m->x_left = fig->x_left;
}

static void write_marker(FILE* out, double px, double py,
                         svp_marker_shape shape, const char* color, double r) {
  switch (shape) {
    case SVP_SQUARE:
      fprintf(out,
              "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
              "fill=\"%s\" stroke=\"black\" stroke-width=\"0.5\"/>\n",
              px - r, py - r, 2 * r, 2 * r, color);
      break;
    case SVP_TRIANGLE:
      fprintf(out,
              "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" "
              "fill=\"%s\" stroke=\"black\" stroke-width=\"0.5\"/>\n",
              px, py - r * 1.15, px - r, py + r * 0.8, px + r, py + r * 0.8,
              color);
      break;
    case SVP_DIAMOND:
      fprintf(out,
              "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f %.2f,%.2f\" "
              "fill=\"%s\" stroke=\"black\" stroke-width=\"0.5\"/>\n",
              px, py - r * 1.3, px + r, py, px, py + r * 1.3, px - r, py,
              color);
      break;
    case SVP_CROSS:
      fprintf(out,
              "<path d=\"M%.2f,%.2fL%.2f,%.2fM%.2f,%.2fL%.2f,%.2f\" "
              "stroke=\"%s\" stroke-width=\"1.5\"/>\n",
              px - r, py - r, px + r, py + r, px - r, py + r, px + r, py - r,
              color);
      break;
    case SVP_CIRCLE:
    default:
      fprintf(out,
              "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" "
              "stroke=\"black\" stroke-width=\"0.5\"/>\n",
              px, py, r, color);
      break;
  }
}

/* A polyline over points [a, b), split at non-finite points. */
static void write_polyline(FILE* out, const mapping* m, const double* x,
                           const double* y, size_t a, size_t b,
                           const char* color, double width, int dashed) {
  size_t i;
  int open = 0;
  for (i = a; i < b; ++i) {
    if (!isfinite(x[i]) || !isfinite(y[i])) {
      if (open) fprintf(out, "\"/>\n");
      open = 0;
      continue;
    }
    if (!open) {
      fprintf(out,
              "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%.2f\" "
              "stroke-linejoin=\"round\" stroke-linecap=\"round\"%s "
              "points=\"",
              color, width,
              dashed ? " stroke-dasharray=\"6,4\"" : "");
      open = 1;
    } else {
      fputc(' ', out);
    }
    fprintf(out, "%.2f,%.2f", map_x(m, x[i]), map_y(m, y[i]));
  }
  if (open) fprintf(out, "\"/>\n");
}

static void write_text(FILE* out, double px, double py, const char* anchor,
                       double size, const char* color, const char* text,
                       const char* extra) {
  char buf[1024];
  svp_escape(text, buf, sizeof(buf));
  fprintf(out,
          "<text x=\"%.2f\" y=\"%.2f\" font-family=\"sans-serif\" "
          "font-size=\"%.1f\" text-anchor=\"%s\" fill=\"%s\"%s>%s</text>\n",
          px, py, size, anchor, color, extra ? extra : "", buf);
}

static void write_axes(const svp_figure* fig, const mapping* m, FILE* out) {
  double first, step, v;
  size_t n, i;
  char label[64];
  fprintf(out,
          "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
          "fill=\"white\" stroke=\"#444\" stroke-width=\"1\"/>\n",
          m->x0, m->y0, m->w, m->h);
  n = svp_nice_ticks(m->xmin, m->xmax, (size_t)(m->w / 70.0) + 2, &first,
                     &step);
  for (i = 0; i < n; ++i) {
    double px;
    v = first + (double)i * step;
    px = map_x(m, v);
    fprintf(out,
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
            "stroke=\"#e4e4e4\" stroke-width=\"1\"/>\n",
            px, m->y0, px, m->y0 + m->h);
    fprintf(out,
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
            "stroke=\"#444\" stroke-width=\"1\"/>\n",
            px, m->y0 + m->h, px, m->y0 + m->h + 5);
    format_tick(v, step, label, sizeof(label));
    write_text(out, px, m->y0 + m->h + 18, "middle", 11, "#222", label, NULL);
  }
  n = svp_nice_ticks(m->ymin, m->ymax, (size_t)(m->h / 45.0) + 2, &first,
                     &step);
  for (i = 0; i < n; ++i) {
    double py;
    v = first + (double)i * step;
    py = map_y(m, v);
    fprintf(out,
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
            "stroke=\"#e4e4e4\" stroke-width=\"1\"/>\n",
            m->x0, py, m->x0 + m->w, py);
    fprintf(out,
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
            "stroke=\"#444\" stroke-width=\"1\"/>\n",
            m->x0 - 5, py, m->x0, py);
    format_tick(v, step, label, sizeof(label));
    write_text(out, m->x0 - 8, py + 4, "end", 11, "#222", label, NULL);
  }
  if (fig->title)
    write_text(out, fig->width / 2, 22, "middle", 14, "#000", fig->title,
               " font-weight=\"bold\"");
  if (fig->xlabel)
    write_text(out, m->x0 + m->w / 2, fig->height - 10, "middle", 12, "#000",
               fig->xlabel, NULL);
  if (fig->ylabel) {
    char extra[96];
    snprintf(extra, sizeof(extra), " transform=\"rotate(-90 %.2f %.2f)\"",
             16.0, m->y0 + m->h / 2);
    write_text(out, 16.0, m->y0 + m->h / 2, "middle", 12, "#000", fig->ylabel,
               extra);
  }
}

/* Data points (all items) inside the pixel box [x, x+w] x [y, y+h]. */
static size_t points_in_box(const svp_figure* fig, const mapping* m,
                            double x, double y, double w, double h) {
  size_t i, j, n = 0;
  for (i = 0; i < fig->item_count; ++i) {
    const item* it = &fig->items[i];
    for (j = 0; j < it->n; ++j) {
      double px, py;
      if (!isfinite(it->x[j]) || !isfinite(it->y[j])) continue;
      px = map_x(m, it->x[j]);
      py = map_y(m, it->y[j]);
      if (px >= x && px <= x + w && py >= y && py <= y + h) n++;
    }
  }
  return n;
}

/* The legend goes in the plot corner covering the fewest data points
 * (top-right, top-left, bottom-right, bottom-left; first wins ties). */
static void legend_corner(const svp_figure* fig, const mapping* m, double w,
                          double h, double* out_x, double* out_y) {
  double xs[4], ys[4];
  size_t best = (size_t)-1, c;
  xs[0] = xs[2] = m->x0 + m->w - w - 8;
  xs[1] = xs[3] = m->x0 + 8;
  ys[0] = ys[1] = m->y0 + 8;
  ys[2] = ys[3] = m->y0 + m->h - h - 8;
  *out_x = xs[0];
  *out_y = ys[0];
  for (c = 0; c < 4; ++c) {
    size_t n = points_in_box(fig, m, xs[c], ys[c], w, h);
    if (n < best) {
      best = n;
      *out_x = xs[c];
      *out_y = ys[c];
    }
  }
}

static void write_legend(const svp_figure* fig, const mapping* m, FILE* out) {
  size_t i, entries = 0, longest = 0;
  double x, y, w, h;
  for (i = 0; i < fig->item_count; ++i)
    if (fig->items[i].label) {
      size_t len = strlen(fig->items[i].label);
      entries++;
      if (len > longest) longest = len;
    }
  if (!entries) return;
  if (longest > 60) longest = 60;
  w = 34.0 + 6.6 * (double)longest;
  h = 8.0 + 17.0 * (double)entries;
  legend_corner(fig, m, w, h, &x, &y);
  fprintf(out,
          "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
          "fill=\"white\" fill-opacity=\"0.88\" stroke=\"#888\"/>\n",
          x, y, w, h);
  entries = 0;
  for (i = 0; i < fig->item_count; ++i) {
    const item* it = &fig->items[i];
    double ry;
    if (!it->label) continue;
    ry = y + 13.0 + 17.0 * (double)entries++;
    if (it->kind == ITEM_SCATTER ||
        (it->kind == ITEM_LEGEND_ONLY && it->dashed))
      write_marker(out, x + 15, ry - 4, it->shape, it->color,
                   it->width < 5 ? it->width : 5);
    else
      fprintf(out,
              "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
              "stroke=\"%s\" stroke-width=\"%.2f\"%s/>\n",
              x + 5, ry - 4, x + 25, ry - 4, it->color,
              it->width < 4 ? it->width : 4,
              (it->kind == ITEM_LINE && it->dashed)
                  ? " stroke-dasharray=\"6,4\""
                  : "");
    write_text(out, x + 30, ry, "start", 11, "#000", it->label, NULL);
  }
}

int svp_write_file(const svp_figure* fig, FILE* out) {
  mapping m;
  size_t i, j;
  if (!fig || !out) return -1;
  resolve_range(fig, &m);
  fprintf(out,
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" "
          "height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
          "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" "
          "fill=\"white\"/>\n",
          fig->width, fig->height, fig->width, fig->height, fig->width,
          fig->height);
  write_axes(fig, &m, out);
  fprintf(out,
          "<defs><clipPath id=\"plotarea\"><rect x=\"%.2f\" y=\"%.2f\" "
          "width=\"%.2f\" height=\"%.2f\"/></clipPath></defs>\n"
          "<g clip-path=\"url(#plotarea)\">\n",
          m.x0, m.y0, m.w, m.h);
  for (i = 0; i < fig->item_count; ++i) {
    const item* it = &fig->items[i];
    switch (it->kind) {
      case ITEM_LINE:
        write_polyline(out, &m, it->x, it->y, 0, it->n, it->color, it->width,
                       it->dashed);
        break;
      case ITEM_COLORED: {
        /* Runs of equal colour become one polyline (shared end point). */
        size_t start = 0;
        for (j = 1; j + 1 <= it->n; ++j) {
          int end_of_run = (j + 1 == it->n) || it->index[j] != it->index[start];
          if (end_of_run) {
            write_polyline(out, &m, it->x, it->y, start, j + 1,
                           it->palette[it->index[start]], it->width, 0);
            start = j;
          }
        }
        break;
      }
      case ITEM_SCATTER:
      case ITEM_MARKER:
        for (j = 0; j < it->n; ++j)
          if (isfinite(it->x[j]) && isfinite(it->y[j]))
            write_marker(out, map_x(&m, it->x[j]), map_y(&m, it->y[j]),
                         it->shape, it->color, it->width);
        if (it->kind == ITEM_MARKER && it->text && isfinite(it->x[0]) &&
            isfinite(it->y[0]))
          write_text(out, map_x(&m, it->x[0]) + it->width + 3,
                     map_y(&m, it->y[0]) - it->width - 2, "start", 11,
                     it->color, it->text, NULL);
        break;
      case ITEM_TEXT:
        if (isfinite(it->x[0]) && isfinite(it->y[0]))
          write_text(out, map_x(&m, it->x[0]), map_y(&m, it->y[0]), "start",
                     11, it->color, it->text, NULL);
        break;
      case ITEM_LEGEND_ONLY:
        break;
    }
  }
  fprintf(out, "</g>\n");
  write_legend(fig, &m, out);
  fprintf(out, "</svg>\n");
  return ferror(out) ? -1 : 0;
}

int svp_write(const svp_figure* fig, const char* path) {
  FILE* f;
  int rc;
  if (!fig || !path) return -1;
  f = fopen(path, "w");
  if (!f) return -1;
  rc = svp_write_file(fig, f);
  if (fclose(f) != 0) rc = -1;
  return rc;
}
