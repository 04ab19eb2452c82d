/*
 * svg_plot.h - a small SVG plotting module for the evaluation figures.
 *
 * One figure = one pair of axes (data coordinates in, pixels out) holding
 * line plots, scatter points, per-vertex coloured polylines (a trajectory
 * coloured by locomotion style), markers with labels, free text, a legend
 * (placed in the plot corner that hides the fewest data points), and axes
 * with "nice" 1-2-5 ticks. Everything is written from code: no
 * figure in docs/img is ever edited by hand.
 *
 * Non-finite data points break a line (a gap), they are never drawn.
 * Colours are any SVG colour string ("#1f77b4", "red").
 * Functions return 0 on success, -1 on bad arguments or out of memory.
 */
#ifndef SVG_PLOT_H
#define SVG_PLOT_H

#include <stddef.h>
#include <stdio.h>

typedef struct svp_figure svp_figure;

typedef enum svp_marker_shape {
  SVP_CIRCLE = 0,
  SVP_SQUARE = 1,
  SVP_TRIANGLE = 2,
  SVP_DIAMOND = 3,
  SVP_CROSS = 4
} svp_marker_shape;

/* A figure of width x height pixels with an optional title. */
svp_figure* svp_create(double width, double height, const char* title);
void svp_destroy(svp_figure* fig);

/* Axis labels (may be NULL). */
int svp_set_labels(svp_figure* fig, const char* xlabel, const char* ylabel);
/* Fix the data range; without it the range covers all data plus 4 %. */
int svp_set_range(svp_figure* fig, double xmin, double xmax, double ymin,
                  double ymax);
/* Same scale on both axes (top-down path figures): the shorter data range
 * is widened so one metre is the same number of pixels along x and y. */
int svp_set_equal_aspect(svp_figure* fig, int on);
/* Flip the vertical axis so y grows downwards (rarely needed). */
int svp_set_y_down(svp_figure* fig, int on);
/* Let x grow towards the left. With x and z of a Y-up right-handed world
 * on the horizontal and vertical axes, this makes the figure the true view
 * from above (+x points left when +z points up the page). */
int svp_set_x_left(svp_figure* fig, int on);

/* A polyline through n points. width in pixels; dashed != 0 draws dashes.
 * label (may be NULL) adds a legend entry. */
int svp_line(svp_figure* fig, const double* x, const double* y, size_t n,
             const char* color, double width, int dashed, const char* label);
/* Scatter points (marker radius in pixels). */
int svp_scatter(svp_figure* fig, const double* x, const double* y, size_t n,
                svp_marker_shape shape, const char* color, double radius,
                const char* label);
/* A polyline whose segment i (from point i to i+1) takes colour
 * palette[index[i]]; consecutive segments of one colour are merged. */
int svp_colored_line(svp_figure* fig, const double* x, const double* y,
                     size_t n, const unsigned* index,
                     const char* const* palette, unsigned palette_count,
                     double width);
/* One marker with an optional text beside it (text not in the legend). */
int svp_marker(svp_figure* fig, double x, double y, svp_marker_shape shape,
               const char* color, double radius, const char* text);
/* Text at a data position. */
int svp_text(svp_figure* fig, double x, double y, const char* text,
             const char* color);
/* A legend entry without data (e.g. explaining a colour of a coloured
 * line). kind: 0 line swatch, 1 marker. */
int svp_legend_entry(svp_figure* fig, const char* label, const char* color,
                     int kind, svp_marker_shape shape);

/* Write the SVG document. */
int svp_write_file(const svp_figure* fig, FILE* out);
int svp_write(const svp_figure* fig, const char* path);

/* "Nice" ticks covering [lo, hi]: step is 1, 2 or 5 times a power of ten,
 * chosen so that at most max_ticks ticks fall inside. Writes the first tick
 * (>= lo) and the step; returns the number of ticks, 0 on bad input. */
size_t svp_nice_ticks(double lo, double hi, size_t max_ticks,
                      double* out_first, double* out_step);

/* Escape text for XML into buf (always NUL-terminated; truncates). */
void svp_escape(const char* text, char* buf, size_t size);

#endif /* SVG_PLOT_H */
