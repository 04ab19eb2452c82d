/*
 * simd.h - whether the SSE2 paths are built. SSE2 is part of the x86-64
 * ABI (and of 32-bit x86 builds that ask for it), so those builds use the
 * four-lane versions; every other target uses the plain C ones, which are
 * the reference the tests hold the SSE2 paths to (bit for bit).
 *
 * Each module keeps its own switch so one path can be tested alone:
 * -DSMGI_QPACK_SSE=0 (rotation decoding, quat_pack.h), -DSMGI_POSE_SSE=0
 * (FK and model matrices, pose_simd.h), -DIK_SSE=0 (foot IK, ik.c); they
 * default to SMGI_SSE2, which -DSMGI_SSE2=0 turns off for all at once.
 */
#ifndef SMG_SIMD_H
#define SMG_SIMD_H

#ifndef SMGI_SSE2
#if defined(__SSE2__) || defined(_M_X64) || \
    (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#define SMGI_SSE2 1
#else
#define SMGI_SSE2 0
#endif
#endif

#endif /* SMG_SIMD_H */
