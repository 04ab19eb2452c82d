/*
 * eval_metrics.h - the measurements of `make eval`, as plain functions on
 * arrays so that each one is unit-tested (tests/eval/test_metrics.c) apart
 * from the runtime and baker that produce the data.
 *
 * Units: metres, seconds, radians. Ground points are (x, z) pairs;
 * 3-D points are (x, y, z) with y up. Quaternions are (x, y, z, w).
 */
#ifndef EVAL_METRICS_H
#define EVAL_METRICS_H

#include <stddef.h>
#include <stdint.h>

/* ---- statistics --------------------------------------------------------- */

typedef struct em_stats {
  size_t count;  /* finite samples used */
  double mean, max, min;
  double median, p99;
} em_stats;

/* Statistics of the finite values among v[0..n). scratch must hold n
 * doubles (it is sorted). With no finite sample, count = 0 and the values
 * are NaN. */
void em_stats_compute(const double* v, size_t n, double* scratch,
                      em_stats* out);
/* Percentile q in [0, 100] of sorted[0..n) by linear interpolation. */
double em_percentile_sorted(const double* sorted, size_t n, double q);
/* Pearson correlation of a and b (NaN when undefined). */
double em_pearson(const double* a, const double* b, size_t n);
/* Least-squares line y = a + b x; returns slope b (NaN if undefined). */
double em_linear_slope(const double* x, const double* y, size_t n,
                       double* out_intercept);

/* ---- paths on the ground ------------------------------------------------ */

/* Length of a polyline of n (x, z) points. */
double em_polyline_length(const double* xz, size_t n);
/* Point at arc length s along the polyline (clamped to its ends). */
void em_polyline_point_at(const double* xz, size_t n, double s,
                          double* out_x, double* out_z);
/* Distance from (px, pz) to the polyline; optionally the arc length of the
 * nearest point on it. n >= 1. */
double em_polyline_distance(const double* xz, size_t n, double px,
                            double pz, double* out_arc);
/* Like em_polyline_distance but only the part of the polyline between
 * arc lengths lo and hi is considered (tracking a point along a path that
 * passes the same place twice, e.g. a circle). */
double em_polyline_distance_window(const double* xz, size_t n, double px,
                                   double pz, double lo, double hi,
                                   double* out_arc);
/* Mean and max distance of m trajectory points from the polyline. */
void em_path_deviation(const double* path_xz, size_t n, const double* traj_xz,
                       size_t m, double* out_mean, double* out_max);

/* Builders for the evaluation paths (step = spacing of points, metres).
 * All start at the origin heading +Z and return the number of points
 * written (at most cap). */
size_t em_path_straight(double length, double step, double* xz, size_t cap);
/* Straight lead, an arc of `angle` radians (positive = left turn, i.e.
 * counter-clockwise seen from above with +Z forward, +X to the left),
 * radius r, then a straight tail. */
size_t em_path_turn(double lead, double radius, double angle, double tail,
                    double step, double* xz, size_t cap);
/* Lead, left arc, right arc (same radius and angle), tail. */
size_t em_path_s_curve(double lead, double radius, double angle, double tail,
                       double step, double* xz, size_t cap);
/* Lead then one full left circle of radius r back to its start, then a
 * short tail leaving along the lead's direction. */
size_t em_path_circle(double lead, double radius, double tail, double step,
                      double* xz, size_t cap);

/* ---- feet --------------------------------------------------------------- */

/* Contacts from foot height and speed: frame i is a contact when the
 * foot's height is below (its lowest height over the sequence +
 * height_margin) and its 3-D speed (central difference) is below
 * max_speed. pos is 3 floats per frame, dt the frame time. */
void em_detect_contacts(const double* pos, size_t n, double dt,
                        double height_margin, double max_speed,
                        uint8_t* out_contact);

typedef struct em_skate {
  size_t contact_frames; /* frame pairs (i-1, i) both in contact */
  double mean_cm, max_cm; /* horizontal slide per contact frame, cm */
  double total_cm;
} em_skate;

/* Foot skate: for every pair of consecutive frames that are both in
 * contact, the horizontal (x, z) displacement of the foot, in cm. */
void em_foot_skate(const double* pos, const uint8_t* contact, size_t n,
                   em_skate* out);

/* Same, for a foot measured at two joints (ankle and toe): for each frame
 * pair the slide is that of whichever joint is lower at the later frame,
 * i.e. of the part of the foot that is planted (heel or ball). */
void em_foot_skate_lowest(const double* ankle, const double* toe,
                          const uint8_t* contact, size_t n, em_skate* out);

/* Rising edges of a contact signal (footfalls): writes frame indices,
 * returns their count (at most cap). A contact already on at frame 0 is
 * not a footfall. */
size_t em_footfalls(const uint8_t* contact, size_t n, size_t* out,
                    size_t cap);

/* First frame >= start at which label[i] == value, or n when none. */
size_t em_first_label(const uint32_t* label, size_t n, size_t start,
                      uint32_t value);

/* ---- phases ------------------------------------------------------------- */

/* Wrap a phase difference (in cycles) to [-0.5, 0.5). */
double em_wrap_half(double cycles);
/* Phase in [0, 1) of each frame from footfall frames (linear between
 * consecutive footfalls of one foot); NaN before the first and after the
 * last footfall. */
void em_phase_from_footfalls(const size_t* falls, size_t count, size_t n,
                             double* out_phase);
/* Circular mean (cycles, in [-0.5, 0.5)) and circular standard deviation
 * (cycles) of phase differences; NaNs skipped. Returns the count used. */
size_t em_circular_stats(const double* d, size_t n, double* out_mean,
                         double* out_std);
/* Unwrap a phase-difference series (cycles) so it is continuous; NaNs are
 * kept and unwrapping continues across them. */
void em_unwrap(const double* d, size_t n, double* out);

/* ---- rigid frames and skeleton error ------------------------------------ */

/* Rotate v by unit quaternion q (x, y, z, w). */
void em_quat_rotate(const double q[4], const double v[3], double out[3]);
/* Express world point p in the frame (origin o, rotation q): q^-1 (p - o). */
void em_to_frame(const double o[3], const double q[4], const double p[3],
                 double out[3]);
/* Rotation of a 4x4 column-major matrix's upper 3x3 as a unit quaternion
 * (the matrix must be a rotation, possibly with uniform scale 1). */
void em_quat_from_matrix(const float m[16], double q[4]);
/* Angle between two unit quaternions, radians in [0, pi]. */
double em_quat_angle(const double a[4], const double b[4]);

/* Forward kinematics: positions (3 per joint, double) and optionally world
 * rotations (4 per joint) from a pose in the blob's layout (root
 * translation then one local quaternion per joint). parents[j] < j,
 * parents[0] = -1; offsets are 3 floats per joint. */
void em_fk(uint32_t joint_count, const int32_t* parents, const float* offsets,
           const float* pose, double* out_positions, double* out_rotations);
/* Hamilton product a * b. */
void em_quat_mul(const double a[4], const double b[4], double out[4]);
/* Ground frame of a pose: the root projected on the floor and the heading
 * of the root's forward (+Z) axis; writes origin (x, 0, z) and the
 * rotation about +Y by that heading. */
void em_ground_frame(const double root_pos[3], const double root_rot[4],
                     double out_origin[3], double out_rot[4]);

/* Mean Euclidean distance over k joints between two point sets (3 per
 * joint), divided by norm (e.g. the spine length). */
double em_mean_joint_error(const double* a, const double* b, size_t k,
                           double norm);

#endif /* EVAL_METRICS_H */
