/*
 * bake_horn.c - Horn 1987, "Closed-form solution of absolute orientation
 * using unit quaternions": the rotation q minimising
 *   sum_i w_i | q a_i q* - b_i |^2
 * is the eigenvector of the largest eigenvalue of the symmetric 4x4 matrix
 * N built from M = sum_i w_i a_i b_i^T (points already expressed relative
 * to their centres). The eigenproblem is solved with cyclic Jacobi sweeps,
 * which are exact enough for a 4x4 and never fail.
 */
#include <math.h>
#include <string.h>

#include "bake_horn.h"

static void jacobi4(double A[4][4], double V[4][4]) {
  int sweep, p, q, i;
  memset(V, 0, 16 * sizeof(double));
  for (i = 0; i < 4; ++i) V[i][i] = 1.0;
  for (sweep = 0; sweep < 64; ++sweep) {
    double off = 0.0;
    for (p = 0; p < 4; ++p)
      for (q = p + 1; q < 4; ++q) off += A[p][q] * A[p][q];
    if (off < 1e-30) break;
    for (p = 0; p < 4; ++p)
      for (q = p + 1; q < 4; ++q) {
        double theta, t, c, s;
        if (fabs(A[p][q]) < 1e-300) continue;
        theta = (A[q][q] - A[p][p]) / (2.0 * A[p][q]);
        t = (theta >= 0 ? 1.0 : -1.0) /
            (fabs(theta) + sqrt(theta * theta + 1.0));
        c = 1.0 / sqrt(t * t + 1.0);
        s = t * c;
        for (i = 0; i < 4; ++i) { /* A = A J */
          double aip = A[i][p], aiq = A[i][q];
          A[i][p] = c * aip - s * aiq;
          A[i][q] = s * aip + c * aiq;
        }
        for (i = 0; i < 4; ++i) { /* A = J^T A */
          double api = A[p][i], aqi = A[q][i];
          A[p][i] = c * api - s * aqi;
          A[q][i] = s * api + c * aqi;
        }
        for (i = 0; i < 4; ++i) {
          double vip = V[i][p], viq = V[i][q];
          V[i][p] = c * vip - s * viq;
          V[i][q] = s * vip + c * viq;
        }
      }
  }
}

void smgb_horn(const double* a, const double* b, const double* w, uint32_t n,
               double q[4]) {
  double S[3][3], N[4][4], V[4][4], best;
  uint32_t i;
  int r, c, bi = 0;
  memset(S, 0, sizeof S);
  for (i = 0; i < n; ++i) {
    double wi = w ? w[i] : 1.0;
    for (r = 0; r < 3; ++r)
      for (c = 0; c < 3; ++c) S[r][c] += wi * a[3 * i + r] * b[3 * i + c];
  }
  /* N in (w, x, y, z) order */
  N[0][0] = S[0][0] + S[1][1] + S[2][2];
  N[0][1] = N[1][0] = S[1][2] - S[2][1];
  N[0][2] = N[2][0] = S[2][0] - S[0][2];
  N[0][3] = N[3][0] = S[0][1] - S[1][0];
  N[1][1] = S[0][0] - S[1][1] - S[2][2];
  N[1][2] = N[2][1] = S[0][1] + S[1][0];
  N[1][3] = N[3][1] = S[2][0] + S[0][2];
  N[2][2] = -S[0][0] + S[1][1] - S[2][2];
  N[2][3] = N[3][2] = S[1][2] + S[2][1];
  N[3][3] = -S[0][0] - S[1][1] + S[2][2];
  jacobi4(N, V);
  best = N[0][0];
  for (r = 1; r < 4; ++r)
    if (N[r][r] > best) {
      best = N[r][r];
      bi = r;
    }
  q[3] = V[0][bi];
  q[0] = V[1][bi];
  q[1] = V[2][bi];
  q[2] = V[3][bi];
  {
    double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(len > 1e-12) || !isfinite(len)) {
      q[0] = q[1] = q[2] = 0.0;
      q[3] = 1.0;
      return;
    }
    for (r = 0; r < 4; ++r) q[r] /= len;
    if (q[3] < 0) /* canonical sign: w >= 0 */
      for (r = 0; r < 4; ++r) q[r] = -q[r];
  }
}
