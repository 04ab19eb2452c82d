/*
 * test_svg.c - the evaluation's SVG plotting module (tools/eval/svg_plot.c):
 * tick choice, escaping, argument checks, and what ends up in the document
 * (gaps at NaN, colour runs, equal aspect, legend, well-formed nesting).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "svg_plot.h"

/* Renders a figure into a heap string (caller frees). */
static char* render(const svp_figure* fig) {
  char* buf = NULL;
  size_t size = 0;
  FILE* f = open_memstream(&buf, &size);
  assert_non_null(f);
  assert_int_equal(svp_write_file(fig, f), 0);
  assert_int_equal(fclose(f), 0);
  assert_non_null(buf);
  return buf;
}

static size_t count_of(const char* hay, const char* needle) {
  size_t n = 0;
  const char* p = hay;
  while ((p = strstr(p, needle)) != NULL) {
    n++;
    p += strlen(needle);
  }
  return n;
}

static void test_nice_ticks(void** state) {
  double first = 0, step = 0;
  (void)state;
  assert_int_equal(svp_nice_ticks(0.0, 10.0, 6, &first, &step), 6);
  assert_true(fabs(first) < 1e-12 && fabs(step - 2.0) < 1e-12);
  assert_int_equal(svp_nice_ticks(0.13, 0.87, 5, &first, &step), 4);
  assert_true(fabs(first - 0.2) < 1e-12 && fabs(step - 0.2) < 1e-12);
  /* span 10.4 with at most 10 ticks: step 1 would give 11, so step 2. */
  assert_int_equal(svp_nice_ticks(-3.3, 7.1, 10, &first, &step), 5);
  assert_true(fabs(first + 2.0) < 1e-12 && fabs(step - 2.0) < 1e-12);
  assert_int_equal(svp_nice_ticks(1e-3, 3e-3, 5, &first, &step), 5);
  assert_true(fabs(step - 5e-4) < 1e-15);
  /* Bad input. */
  assert_int_equal(svp_nice_ticks(1.0, 1.0, 5, &first, &step), 0);
  assert_int_equal(svp_nice_ticks(2.0, 1.0, 5, &first, &step), 0);
  assert_int_equal(svp_nice_ticks(NAN, 1.0, 5, &first, &step), 0);
  assert_int_equal(svp_nice_ticks(0.0, 1.0, 1, &first, &step), 0);
}

static void test_escape(void** state) {
  char buf[64];
  (void)state;
  svp_escape("a<b & \"c\">d", buf, sizeof(buf));
  assert_string_equal(buf, "a&lt;b &amp; &quot;c&quot;&gt;d");
  /* Truncation never splits an entity and always terminates. */
  svp_escape("&&&&", buf, 8);
  assert_string_equal(buf, "&amp;");
  svp_escape(NULL, buf, sizeof(buf));
  assert_string_equal(buf, "");
}

static void test_bad_arguments(void** state) {
  double x[2] = {0, 1}, y[2] = {0, 1};
  unsigned idx[1] = {3};
  const char* pal[2] = {"red", "blue"};
  svp_figure* fig;
  (void)state;
  assert_null(svp_create(10, 10, NULL));
  assert_null(svp_create(NAN, 400, NULL));
  fig = svp_create(400, 300, "t");
  assert_non_null(fig);
  assert_int_equal(svp_line(NULL, x, y, 2, "red", 1, 0, NULL), -1);
  assert_int_equal(svp_line(fig, NULL, y, 2, "red", 1, 0, NULL), -1);
  assert_int_equal(svp_line(fig, x, y, 2, "red", 0, 0, NULL), -1);
  assert_int_equal(svp_scatter(fig, x, y, 2, (svp_marker_shape)9, "r", 2, 0),
                   -1);
  assert_int_equal(svp_colored_line(fig, x, y, 2, idx, pal, 2, 1.0), -1);
  assert_int_equal(svp_set_range(fig, 1, 0, 0, 1), -1);
  assert_int_equal(svp_set_range(fig, 0, 1, 0, NAN), -1);
  assert_int_equal(svp_text(fig, 0, 0, NULL, "red"), -1);
  assert_int_equal(svp_write_file(fig, NULL), -1);
  svp_destroy(fig);
  svp_destroy(NULL);
}

static void test_document_content(void** state) {
  double x[5] = {0, 1, NAN, 3, 4}, y[5] = {0, 1, 2, 3, 4};
  double cx[5] = {0, 1, 2, 3, 4}, cy[5] = {0, 0, 0, 0, 0};
  unsigned idx[4] = {0, 0, 1, 0};
  const char* pal[2] = {"#0000ff", "#ff0000"};
  svp_figure* fig = svp_create(640, 480, "A & B");
  char* doc;
  (void)state;
  assert_non_null(fig);
  assert_int_equal(svp_set_labels(fig, "time (s)", "error <cm>"), 0);
  assert_int_equal(svp_line(fig, x, y, 5, "#123456", 2, 1, "gap line"), 0);
  assert_int_equal(svp_colored_line(fig, cx, cy, 5, idx, pal, 2, 3), 0);
  assert_int_equal(svp_scatter(fig, cx, cy, 5, SVP_DIAMOND, "green", 3, "pts"),
                   0);
  assert_int_equal(svp_marker(fig, 2, 2, SVP_TRIANGLE, "orange", 5, "splice"),
                   0);
  assert_int_equal(svp_legend_entry(fig, "walk", "#0000ff", 0, SVP_CIRCLE), 0);
  doc = render(fig);
  /* Title and labels escaped. */
  assert_non_null(strstr(doc, ">A &amp; B</text>"));
  assert_non_null(strstr(doc, ">error &lt;cm&gt;</text>"));
  /* The NaN splits the first line into two dashed polylines. */
  assert_int_equal(count_of(doc, "stroke=\"#123456\""), 3); /* 2 + legend */
  assert_int_equal(count_of(doc, "stroke-dasharray"), 3);
  /* Colour runs: blue [0..2], red [2..3], blue [3..4]. */
  assert_int_equal(count_of(doc, "<polyline fill=\"none\" stroke=\"#0000ff\""),
                   2);
  assert_int_equal(count_of(doc, "<polyline fill=\"none\" stroke=\"#ff0000\""),
                   1);
  /* Five diamonds + one legend diamond, one triangle. */
  assert_int_equal(count_of(doc, "fill=\"green\""), 6);
  assert_int_equal(count_of(doc, "fill=\"orange\" stroke=\"black\""), 1);
  assert_non_null(strstr(doc, ">splice</text>"));
  /* Legend entries. */
  assert_non_null(strstr(doc, ">gap line</text>"));
  assert_non_null(strstr(doc, ">walk</text>"));
  assert_non_null(strstr(doc, ">pts</text>"));
  /* Well-formed enough: one root, groups closed, every text closed. */
  assert_int_equal(count_of(doc, "<svg "), 1);
  assert_int_equal(count_of(doc, "</svg>"), 1);
  assert_int_equal(count_of(doc, "<g "), count_of(doc, "</g>"));
  assert_int_equal(count_of(doc, "<text "), count_of(doc, "</text>"));
  free(doc);
  svp_destroy(fig);
}

/* Pixel length of the first polyline with the given stroke colour. */
static double polyline_pixel_length(const char* doc, const char* color) {
  char key[64];
  const char* p;
  double x0, y0, x1, y1;
  snprintf(key, sizeof(key), "stroke=\"%s\"", color);
  p = strstr(doc, key);
  assert_non_null(p);
  p = strstr(p, "points=\"");
  assert_non_null(p);
  assert_int_equal(sscanf(p, "points=\"%lf,%lf %lf,%lf", &x0, &y0, &x1, &y1),
                   4);
  return hypot(x1 - x0, y1 - y0);
}

static void test_equal_aspect(void** state) {
  /* A 1 m segment along x and one along y; data 10 m wide, 1 m tall. */
  double hx[2] = {0, 1}, hy[2] = {0, 0}, vx[2] = {0, 0}, vy[2] = {0, 1};
  double fx[2] = {-5, 5}, fy[2] = {0, 1};
  svp_figure* fig = svp_create(600, 400, NULL);
  char* doc;
  double lh, lv;
  (void)state;
  assert_int_equal(svp_line(fig, hx, hy, 2, "#aa0000", 1, 0, NULL), 0);
  assert_int_equal(svp_line(fig, vx, vy, 2, "#00aa00", 1, 0, NULL), 0);
  assert_int_equal(svp_scatter(fig, fx, fy, 2, SVP_CIRCLE, "#000", 1, NULL),
                   0);
  assert_int_equal(svp_set_equal_aspect(fig, 1), 0);
  doc = render(fig);
  lh = polyline_pixel_length(doc, "#aa0000");
  lv = polyline_pixel_length(doc, "#00aa00");
  assert_true(lh > 10.0);
  assert_true(fabs(lh - lv) < 0.05);
  free(doc);
  /* Without equal aspect the 1 m vertical segment is much longer. */
  assert_int_equal(svp_set_equal_aspect(fig, 0), 0);
  doc = render(fig);
  lh = polyline_pixel_length(doc, "#aa0000");
  lv = polyline_pixel_length(doc, "#00aa00");
  assert_true(lv > 3.0 * lh);
  free(doc);
  svp_destroy(fig);
}

static void test_x_left_mirrors(void** state) {
  /* With x growing leftwards, the point x = 1 is drawn left of x = 0. */
  double x[2] = {0, 1}, y[2] = {0, 0};
  svp_figure* fig = svp_create(400, 300, NULL);
  char* doc;
  const char* p;
  double x0, y0, x1, y1;
  (void)state;
  assert_int_equal(svp_line(fig, x, y, 2, "#abcdef", 1, 0, NULL), 0);
  assert_int_equal(svp_set_x_left(fig, 1), 0);
  doc = render(fig);
  p = strstr(doc, "points=\"");
  assert_non_null(p);
  assert_int_equal(sscanf(p, "points=\"%lf,%lf %lf,%lf", &x0, &y0, &x1, &y1),
                   4);
  assert_true(x1 < x0);
  free(doc);
  svp_destroy(fig);
}

/* x of the legend box (the first rect with fill-opacity). */
static double legend_x(const char* doc) {
  const char* p = strstr(doc, "fill-opacity");
  double x = -1, y = -1;
  assert_non_null(p);
  while (p > doc && strncmp(p, "<rect", 5) != 0) p--;
  assert_int_equal(sscanf(p, "<rect x=\"%lf\" y=\"%lf\"", &x, &y), 2);
  return x;
}

static void test_legend_avoids_data(void** state) {
  /* Many points in the top-right corner: the legend moves left. */
  double x[50], y[50];
  size_t i;
  svp_figure* fig = svp_create(600, 400, NULL);
  char* doc;
  double lx_crowded, lx_free;
  (void)state;
  for (i = 0; i < 50; ++i) {
    x[i] = 9.0 + 0.02 * (double)i;
    y[i] = 9.0 + 0.02 * (double)i;
  }
  assert_int_equal(svp_scatter(fig, x, y, 50, SVP_CIRCLE, "red", 2, "dots"),
                   0);
  assert_int_equal(svp_set_range(fig, 0, 10, 0, 10), 0);
  doc = render(fig);
  lx_crowded = legend_x(doc);
  free(doc);
  assert_true(lx_crowded < 300.0); /* left half */
  /* Points moved to the bottom-left: the legend stays top-right. */
  for (i = 0; i < 50; ++i) x[i] = y[i] = 0.5 + 0.02 * (double)i;
  svp_destroy(fig);
  fig = svp_create(600, 400, NULL);
  assert_int_equal(svp_scatter(fig, x, y, 50, SVP_CIRCLE, "red", 2, "dots"),
                   0);
  assert_int_equal(svp_set_range(fig, 0, 10, 0, 10), 0);
  doc = render(fig);
  lx_free = legend_x(doc);
  free(doc);
  assert_true(lx_free > 300.0);
  svp_destroy(fig);
}

static void test_write_file(void** state) {
  char path[] = "/tmp/smg-test-svg-XXXXXX";
  double x[3] = {0, 1, 2}, y[3] = {1, 0, 1};
  svp_figure* fig = svp_create(300, 200, "file");
  FILE* f;
  char head[64] = {0};
  int fd;
  (void)state;
  fd = mkstemp(path);
  assert_true(fd >= 0);
  assert_int_equal(svp_line(fig, x, y, 3, "red", 1, 0, NULL), 0);
  assert_int_equal(svp_write(fig, path), 0);
  f = fopen(path, "r");
  assert_non_null(f);
  assert_true(fread(head, 1, sizeof(head) - 1, f) > 0);
  fclose(f);
  assert_non_null(strstr(head, "<?xml"));
  remove(path);
  assert_int_equal(svp_write(fig, "/nonexistent-dir/x.svg"), -1);
  svp_destroy(fig);
  close(fd);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_nice_ticks),
      cmocka_unit_test(test_escape),
      cmocka_unit_test(test_bad_arguments),
      cmocka_unit_test(test_document_content),
      cmocka_unit_test(test_equal_aspect),
      cmocka_unit_test(test_x_left_mirrors),
      cmocka_unit_test(test_legend_avoids_data),
      cmocka_unit_test(test_write_file),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
