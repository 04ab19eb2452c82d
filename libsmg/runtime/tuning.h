/*
 * tuning.h - every tuning constant of the runtime in one place, grouped by
 * the stage that uses it. Distances are metres, times seconds, angles
 * radians, unless a name says otherwise. None of these are user settings:
 * what a user may change per character is in smg_character_desc (smg.h),
 * whose defaults are settled in one function, smgi_settle (settings.c),
 * from the SMGI_DEFAULT_* values and the stages' defaults below
 * (SMGI_STEER_TURN_LIMIT, _SLIDE_RATIO, _STOP_SECONDS, SMGI_IK_SWING_CLEAR).
 */
#ifndef SMG_TUNING_H
#define SMG_TUNING_H

/* ---- character defaults (settings.c) and limits (character.c) ---- */
/* 512 points (6 KB) keep a default character within 16 KiB in all; a
 * mouse-drawn path resampled every few centimetres fits, and longer paths
 * set path_capacity (12 bytes per point). */
#define SMGI_DEFAULT_PATH_CAPACITY 512u
#define SMGI_DEFAULT_CONSTRAINT_CAPACITY 32u
#define SMGI_MAX_PATH_CAPACITY (1u << 26)
#define SMGI_MAX_CONSTRAINT_CAPACITY (1u << 16)
#define SMGI_DEFAULT_HORIZON 2.0f     /* seconds planned ahead */
#define SMGI_MAX_HORIZON 30.0f
#define SMGI_DEFAULT_THRESHOLD 0.25f  /* the paper's distance error bound */
#define SMGI_DEFAULT_WINDOW 0.25f     /* crossfade when the blob has none */

/* ---- path queries (path.c) ---- */
#define SMGI_PATH_WALK_LIMIT 4u      /* segments walked from a hint before
                                        the galloping search */
#define SMGI_PATH_PROJECT_LIMIT 256u /* descent steps of a local projection */
#define SMGI_PATH_PROJECT_TIE 0.02f  /* metres: a later pass of the path
                                        must be nearer by this to win */
#define SMGI_PATH_AHEAD_OFF 0.2f     /* metres off the path beyond which
                                        progress looks for a later pass
                                        nearer the character ... */
#define SMGI_PATH_AHEAD_ARC 2.0f     /* ... within this much arc ahead */

/* ---- lower-body queue (lower.h) ---- */
#define SMGI_QUEUE_CAP 64u /* committed + planned lower edges (power of 2) */

/* ---- planner (planner.c: ranking, backtracking, committing) ---- */
#define SMGI_MAX_CANDIDATES 64u  /* out-edges ranked per planning step */
#define SMGI_PLAN_BUDGET 256u    /* edge evaluations per step (~25 us at
                                    most) beyond what the step needs */
#define SMGI_MAX_RANK 3u         /* backtracking tries per node */
#define SMGI_MAX_BACKTRACKS 8u   /* backtracks before accepting the best */
#define SMGI_END_EPS 0.3f        /* metres before the path's end that count
                                    as there (nothing more to follow) */
#define SMGI_YIELD_ERROR 0.8f    /* mean distance from the path beyond
                                    the steering's reach (m) over which the
                                    wanted style yields to the agile one */
#define SMGI_YIELD_DRIFT 0.25f   /* ... or the character's distance from
                                    the path (m) while the best sequence
                                    stays as far off beyond the reach:
                                    failing to follow (a run's bound is
                                    its own cut, planner.c yield_drift) */
#define SMGI_SEQ_COMMIT_FRAMES 12.0f /* frames of the best sequence
                                        committed at once */

/* ---- sequence search (plan_search.c) ---- */
#define SMGI_SEQ_SECONDS 2.0f    /* motion a candidate sequence covers */
#define SMGI_SEQ_BUDGET 256u     /* edge evaluations per ranking */
#define SMGI_SEQ_BUDGET_STEER 128u /* ... while root steering is on: what
                                      the search leaves, steering absorbs */
#define SMGI_SEQ_BRANCHES 6u     /* choices searched below a candidate */
#define SMGI_SEQ_MAX_DEPTH 48u   /* edges followed without a choice */
#define SMGI_SEQ_MAX_KIDS 8u     /* out-edges tried at one branch */
#define SMGI_SEQ_PATH_CAP 64u    /* edges of one sequence */
#define SMGI_HEADING_WEIGHT 0.4f /* metres of error per radian */
#define SMGI_STYLE_WEIGHT 3.0f   /* metres of penalty per hop to the wanted
                                    style: style constraints dominate path
                                    error */
#define SMGI_END_SPEED_WEIGHT 0.5f /* at the end prefer motion that travels
                                      less (metres per m/s) */
#define SMGI_LOST_DISTANCE 1.5f  /* off the path by more: "lost" */
#define SMGI_HEADING_WEIGHT_LOST 2.0f   /* metres per radian when lost */
#define SMGI_LOST_DISTANCE_WEIGHT 0.25f /* and distance counts less */
#define SMGI_TRAVEL_WEIGHT 0.3f  /* metres per radian of travel vs facing */
#define SMGI_PURSUIT_M 1.0f      /* heading aims this far ahead on the path */
#define SMGI_TURN_WEIGHT 1.0f    /* metres per radian of turn out of reach */

/* ---- derived tables (graph_derived.c) ---- */
#define SMGI_TRAIL_SAMPLES 4u    /* samples of a node's natural future */
#define SMGI_TRAIL_STEP_SECONDS 0.5f
#define SMGI_TURN_SECONDS 3.0f   /* horizon of node_next.turn */
#define SMGI_STOP_FROUDE 0.5f    /* a style stops in one step only below
                                    the walk-run transition: its mean
                                    speed v with v^2 / (g * leg length)
                                    under this (people change gait near
                                    0.5; 2.0 m/s for a 0.8 m leg) */
#define SMGI_GRAVITY 9.81f       /* m/s^2 */

/* ---- progress along the path (step.c) ---- */
#define SMGI_END_NEAR 1.0f /* metres from the last point that count as
                              arrived */

/* ---- upper body (upper.c) ---- */
#define SMGI_SPLICE_WINDOW 20u   /* lower frames searched for a splice */
#define SMGI_SPLICE_LEAD 0.3f    /* metres before the point to start looking */
#define SMGI_FORCE_DISTANCE 1.0f /* metres past the point before forcing */
#define SMGI_FORCE_SECONDS 1.0f  /* or seconds of waiting (no progress) */

/* ---- synchronization (sync.c) ---- */
#define SMGI_SYNC_LOWER 8u     /* DTW window, lower frames */
#define SMGI_SYNC_UPPER 16u    /* DTW window, upper frames */
#define SMGI_SYNC_RATE_MIN 0.5f
#define SMGI_SYNC_RATE_MAX 2.0f
#define SMGI_SYNC_SMOOTH 0.3f  /* rate follows its target by this per frame */
#define SMGI_SYNC_PHASE_LOCK 4.0f /* rate change per cycle of phase error:
                                     an error closes over about a quarter
                                     cycle */

/* ---- pose (pose.c) ---- */
#define SMGI_POSE_STACK_JOINTS 64u /* pose scratch on the stack up to here
                                      (1 KiB) */

/* ---- foot IK (ik.c) ---- */
#define SMGI_IK_BLEND 0.1f      /* seconds to blend a planted foot in */
#define SMGI_IK_LIFT 0.05f      /* leg lengths the animated toe rises,
                                   beyond SMGI_IK_CLEAR, while a released
                                   foot's correction returns (about 4 cm):
                                   it returns in the air, not while the toe
                                   pushes off. A fixed 0.1 s return added
                                   27 cm/s to toes still within 2 cm of the
                                   floor (02_01 + 06_01); a fixed 0.2 s
                                   one ran into the low swing of the
                                   synthetic walk on a Mixamo rig. */
#define SMGI_IK_CLEAR 0.03f     /* leg lengths (about 2.5 cm) of toe roll
                                   near the floor: a released toe below
                                   this above where it was held, or a
                                   landing toe below this above where the
                                   foot was held last, is still on the
                                   floor */
#define SMGI_IK_LET_GO 0.15f    /* leg lengths of the animated toe's own
                                   travel over which a released foot lets
                                   its correction go at most (a foot that
                                   shuffles on without lifting) */
#define SMGI_IK_SWING_CLEAR 0.04f /* leg lengths (about 3.5 cm) a fast
                                     swinging toe clears the floor by, by
                                     default: real swings pass 1-2 cm
                                     above it (the toe joint of the second
                                     studio's data at 3.5-4 m/s) */
#define SMGI_IK_SWING_SLOW 1.0f /* leg lengths per second of toe speed over
                                   the ground below which a foot is not
                                   swinging (standing, rolling, landing:
                                   under 0.5 on the walks measured) ... */
#define SMGI_IK_SWING_FAST 2.0f /* ... and from which it is (a walk's swing
                                   peaks at 3-5) */
#define SMGI_IK_SWING_RISE 0.1f /* seconds over which swing clearance
                                   lifts a foot at the fastest ... */
#define SMGI_IK_SWING_FALL 0.05f /* ... and lowers it */
#define SMGI_IK_ITERATIONS 8u   /* CCD sweeps at most */
#define SMGI_IK_RELEASE 0.35f   /* anchor drift, in leg lengths, that lets
                                   a contact go */
#define SMGI_IK_TOLERANCE 2e-4f /* metres beyond the closest the leg can
                                   reach (2 mm let a held toe jitter by
                                   up to 6 cm/s at 30 Hz) */

/* ---- uneven ground (ik.c, smg_character_set_ground) ---- */
#define SMGI_GROUND_ROOT_SECONDS 0.2f /* time constant the root follows the
                                         ground under it with: a stair edge
                                         passing under the root raises the
                                         body over a step's time, not in
                                         one frame */
#define SMGI_GROUND_FOOT_RATE 2.0f /* leg lengths per second a toe's ground
                                      height moves at least (more while
                                      the toe moves faster over the
                                      ground: 45 degrees) */
#define SMGI_GROUND_REACH 0.98f /* fraction of hip-knee-ankle length a leg
                                   may be stretched to before the pelvis
                                   is lowered (never straight: a straight
                                   knee has no plane left to bend in) */
#define SMGI_GROUND_DROP_FALL 4.0f /* leg lengths per second the pelvis
                                      may lower at most ... */
#define SMGI_GROUND_DROP_RISE 1.0f /* ... and rise back */

/* ---- root steering (steer.c) ---- */
/* Defaults of the public limits (smg_character_desc). */
#define SMGI_STEER_TURN_LIMIT 3.0f    /* rad/s of additive heading correction */
#define SMGI_STEER_SLIDE_RATIO 0.25f  /* translation per metre of motion */
#define SMGI_STEER_STOP_SECONDS 1.0f  /* braking time at the end */
/* The method's constants: they are shapes of the control (time constants,
 * fractions), not fitted to any clip. */
#define SMGI_STEER_CLIP_SCALE 0.5f    /* may add or remove this much of the
                                    clip's own turning (0.5x .. 1.5x) */
#define SMGI_STEER_TURN_RADIUS 0.5f   /* additive turning <= speed / radius: none
                                    while standing, tight while walking */
#define SMGI_STEER_HEADING_TIME 0.25f /* heading error removed over this time */
#define SMGI_STEER_SLIDE_TIME 0.3f    /* lateral error removed over this time */
#define SMGI_STEER_TURN_ACCEL 8.0f    /* rad/s^2: the correction rate's change */
#define SMGI_STEER_SLIDE_ACCEL 2.0f   /* m/s^2 */
#define SMGI_STEER_SWAY 0.03f         /* m: lateral offsets within the hips'
                                    own sway are left alone */
#define SMGI_STEER_SMOOTH 0.25f       /* s: low-pass of the clip's own motion */
#define SMGI_STEER_LEAD_SMOOTH 0.5f   /* s: low-pass of the motion's facing
                                    and travel for its lead (about half a
                                    stride: the sway and twist of each
                                    step mostly averaged out) */
#define SMGI_STEER_LEAD_SWAY 0.04f    /* rad: what the low-pass leaves of the
                                    sway (a stride's hips swing +-8 deg
                                    about the travel, a third of it
                                    passes): a lead within it is noise */
#define SMGI_STEER_BODY_REST 1e-4f   /* rad: the body's turn onto its
                                    travel (steer.c) this near none
                                    fading out is none */
#define SMGI_STEER_LEAD_MIN 0.5f      /* the low-passed facing's length below
                                    which it is no direction (a spin) */
#define SMGI_STEER_LEAD_SPEED 0.2f    /* m/s: travel slower than this has no
                                    direction to face */
#define SMGI_STEER_FUTURE 0.4f        /* s: the clip's direction is where its
                                    root is this far ahead */
#define SMGI_STEER_LOOK_TIME 0.6f     /* s: the pursuit point's lead ... */
#define SMGI_STEER_LOOK_MIN 0.5f      /* ... in metres, at least */
#define SMGI_STEER_LOOK_MAX 2.0f      /* ... and at most */
#define SMGI_STEER_CURVE_AHEAD 1.5f   /* m: path curvature measured over this */
#define SMGI_STEER_AHEAD_SAMPLES 8u   /* half-spans of it looked ahead at most
                                         for a turn to slow down for */
#define SMGI_STEER_GRIP 0.5f          /* sideways acceleration a body takes in
                                         a turn, in g: a shoe's friction
                                         on a floor (0.5-0.8) at its low end */
#define SMGI_GRAVITY 9.81f            /* m/s^2 */
#define SMGI_STEER_RATE_MIN 0.8f      /* slowest playback for a tight turn
                                         (slower is slow motion; the rest
                                         of the slowing is shorter strides) */
#define SMGI_STEER_RATE_ACCEL 1.0f    /* playback rate change per second */
#define SMGI_STEER_CUT_TURN 2.0f      /* a body cutting a hairpin pivots over
                                         its planted foot: this many times
                                         the turn limit (within the
                                         tightest turning circle) */
#define SMGI_STEER_CUT_SLIDE 0.5f     /* ... and slides at this share of
                                         the slide ratio (7 degrees of
                                         crabbing at most, not 14) */
#define SMGI_STEER_STOP_NEAR 1.0f     /* a stop frame lands this near the end */
#define SMGI_STEER_ONE_FOOT 0.5f      /* m: a stop frame with one foot down
                                    counts as this much further */
#define SMGI_STEER_NO_FOOT 1.0f       /* ... with no foot down */
#define SMGI_STEER_REST_RATE 0.03f    /* below this rate the stop is made */
#define SMGI_STEER_BRAKE_FLOOR SMGI_STEER_RATE_MIN /* braking and starting
                                         play at least this fraction of real
                                         time: the one floor below which
                                         playback reads as slow motion */
#define SMGI_STEER_PLAN_WEIGHT 0.5f   /* the planner counts an error the
                                         steering can remove at this
                                         fraction of itself */
#define SMGI_STEER_REPLAN_TURN 0.7f   /* rad of correction (40 deg) ... */
#define SMGI_STEER_REPLAN_MOVE 0.5f   /* ... or metres of it since the plan
                                         was chosen: plan again */
#define SMGI_STEER_LAG_STEPS 32u      /* steps the correction pending for
                                         planned entries is composed before
                                         it is written into them (bounds
                                         its rounding; steer.c) */
#define SMGI_STEER_SETTLE_SECONDS 1.5f /* s of walking before braking in
                                          which a run's stop wants the
                                          graph's stop style (planner.c) */
#define SMGI_STEER_STOP_SCAN 1.0f     /* s of frames beyond the braking
                                         distance searched for a stop */
#define SMGI_STEER_STRIDE_STOP 0.4f  /* share of its strides a run keeps
                                         at least while braking to a stop */
#define SMGI_STEER_STOP_DECEL 0.25f /* of gravity: a run's deceleration
                                         over its last metres (2.5 m/s^2) */
#define SMGI_STEER_HORIZON 1.0f       /* s planned ahead while steering
                                         follows, away from the end */

/* ---- standing still (rest.c) ---- */
#define SMGI_REST_FOOT_FLAT 0.15f /* s a standing foot takes to lie flat
                                     (heel or toe down) */
#define SMGI_REST_SETTLE_MIN 0.3f /* s the hips take to come to stand over
                                     the feet (and the standing motion to
                                     fade in), at least ... */
#define SMGI_REST_SETTLE_MAX 1.0f /* ... and at most */
#define SMGI_REST_STEP_SHARE 0.55f /* of that time the settling step takes
                                      at most ... */
#define SMGI_REST_LAND_LEFT 0.05f  /* ... and it lands while the hips still
                                      have at least this many leg lengths
                                      (4 cm) to go, besides the standing
                                      motion's own sway: they come to stand
                                      over both feet */
#define SMGI_REST_STEP_MIN \
  (SMGI_REST_STEP_SHARE * SMGI_REST_SETTLE_MIN) /* s: the quickest
                                                   settling step */
#define SMGI_REST_FADE_OUT 0.6f  /* s: the standing motion and the glide
                                    fade out as the walk begins */
#define SMGI_REST_LIFT 0.08f     /* leg lengths a stepping foot rises at
                                    most (6-7 cm) */
#define SMGI_REST_STEP_OVER 0.7f /* of a step the foot moves over the
                                    ground in (the middle: lifted) */
#define SMGI_REST_GLIDE_MAX 0.6f /* leg lengths the hips glide at most */
#define SMGI_REST_PURSUIT 1.0f   /* m along a new path: where to face */
#define SMGI_REST_TURN_MIN 1.05f /* rad (60 deg): a path starting further
                                    off the facing is met by turning on the
                                    spot first */
#define SMGI_REST_TURN_RATE 3.0f /* rad/s of turning on the spot, mean */
#define SMGI_REST_TURN_STEP 1.6f /* rad of turn per step at most */
#define SMGI_REST_REJOIN_SECONDS 0.2f /* s a lifted foot takes to join
                                         the locomotion's */
#define SMGI_REST_KEEP_SECONDS 1.5f /* s a foot stays where it stood when
                                       walking on, at most */

#endif /* SMG_TUNING_H */
