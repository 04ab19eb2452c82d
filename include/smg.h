/*
 * smg.h - libsmg, the Splicing Motion Graphs runtime.
 *
 * libsmg makes game characters follow paths that a player draws, using real
 * motion-capture motion: the lower body walks or runs along the path, chosen
 * from a locomotion motion graph, while the upper body performs independent
 * actions (punching, dribbling, ...) chosen from an action motion graph and
 * spliced on at the pelvis (Tamada, Kitaoka, Kitamura, "Splicing Motion
 * Graphs"). All heavy work happens offline in `smg-bake`, which writes one
 * binary *graph blob*; this header is everything an engine needs at run time.
 *
 * Reading order for a new user:
 *   1. Load a graph:      smg_graph_load_file() / smg_graph_load_memory()
 *   2. Make characters:   smg_character_create()
 *   3. Give them a path:  smg_character_set_path(), _append_path(),
 *                         _add_transition() (change walk/run at a distance),
 *                         _add_splice()     (change upper-body action).
 *   4. Every frame:       smg_character_step(ch, dt), then read the pose with
 *                         smg_character_get_local_pose() or
 *                         smg_character_get_model_matrices().
 *   5. Tear down:         smg_character_destroy(), then smg_graph_destroy().
 *
 * Conventions (they hold for every function here):
 *   - Every fallible call returns an smg_result; SMG_OK (0) is success and
 *     outputs are written only on success. smg_result_string() names a code.
 *   - Units are metres and seconds. Y is up; the ground is the (x, z) plane.
 *     A heading is an angle in radians about +Y; heading 0 faces +Z and the
 *     forward direction for heading h is (sin h, 0, cos h).
 *   - Quaternions are 4 floats (x, y, z, w). Matrices are 4x4 floats in
 *     column-major order (OpenGL, cglm, Godot and Unity all accept this).
 *   - Descriptor structs are zero-initialised by the caller, who sets
 *     struct_size = sizeof(the struct) and then only the fields they care
 *     about: a zero field means "use the default" documented beside it.
 *     struct_size lets later versions grow structs without breaking old
 *     callers. Structs crossing the ABI use fixed-width integers only.
 *   - Memory: all allocation happens in *_load and *_create, through the
 *     optional allocator hooks. smg_character_step() and the pose functions
 *     never allocate, never do I/O and never block.
 *   - Threads: an smg_graph is immutable after loading and may be shared by
 *     any number of characters on any number of threads. One character must
 *     be used by one thread at a time (no internal locks). Loading/destroying
 *     graphs is not thread-safe with respect to the same graph.
 *   - Lifetime rule: a graph must outlive its characters. smg_graph_destroy()
 *     on a graph that still has live characters returns SMG_ERROR_IN_USE and
 *     destroys nothing.
 */
#ifndef SMG_H
#define SMG_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && defined(SMG_BUILD_SHARED)
#define SMG_API __declspec(dllexport)
#elif defined(_WIN32) && defined(SMG_USE_SHARED)
#define SMG_API __declspec(dllimport)
#elif defined(__GNUC__) || defined(__clang__)
#define SMG_API __attribute__((visibility("default")))
#else
#define SMG_API
#endif

/* ------------------------------------------------------------------------ */
/* Version                                                                  */
/* ------------------------------------------------------------------------ */

#define SMG_VERSION_MAJOR 0
#define SMG_VERSION_MINOR 1
#define SMG_VERSION_PATCH 0
/* (major << 16) | (minor << 8) | patch */
#define SMG_VERSION \
  ((SMG_VERSION_MAJOR << 16) | (SMG_VERSION_MINOR << 8) | SMG_VERSION_PATCH)

/* Graph-blob format versions this build reads (see docs/blob-format.md). */
#define SMG_BLOB_VERSION_MIN 2
#define SMG_BLOB_VERSION_MAX 2

/* The version of the library actually linked, encoded like SMG_VERSION.
 * Compare with SMG_VERSION to detect a header/library mismatch. */
SMG_API uint32_t smg_version(void);

/* ------------------------------------------------------------------------ */
/* Results                                                                  */
/* ------------------------------------------------------------------------ */

typedef enum smg_result {
  SMG_OK = 0,
  SMG_ERROR_INVALID_ARGUMENT = 1, /* NULL pointer, NaN, bad struct_size ... */
  SMG_ERROR_OUT_OF_MEMORY = 2,    /* the allocator returned NULL */
  SMG_ERROR_IO = 3,               /* file could not be opened or read */
  SMG_ERROR_BLOB_TRUNCATED = 4,   /* blob shorter than its header says */
  SMG_ERROR_BLOB_MAGIC = 5,       /* not a graph blob */
  SMG_ERROR_BLOB_ENDIAN = 6,      /* written on a machine of other byte order */
  SMG_ERROR_BLOB_VERSION = 7,     /* format version outside MIN..MAX */
  SMG_ERROR_BLOB_ALIGNMENT = 8,   /* blob memory or a section misaligned */
  SMG_ERROR_BLOB_CHECKSUM = 9,    /* payload does not match its checksum */
  SMG_ERROR_BLOB_SECTION = 10,    /* section table entry invalid/missing */
  SMG_ERROR_BLOB_INDEX = 11,      /* an index inside a section out of range */
  SMG_ERROR_BLOB_VALUE = 12,      /* a non-finite or impossible value */
  SMG_ERROR_UNKNOWN_STYLE = 13,   /* style index/name not in the graph */
  SMG_ERROR_UNKNOWN_ACTION = 14,  /* action index/name not in the graph */
  SMG_ERROR_OUT_OF_RANGE = 15,    /* index or arc length beyond valid range */
  SMG_ERROR_CAPACITY = 16,        /* a fixed capacity (path, constraints) full */
  SMG_ERROR_BUFFER_TOO_SMALL = 17,/* caller buffer smaller than needed */
  SMG_ERROR_IN_USE = 18,          /* graph still has live characters */
  SMG_ERROR_NOT_FOUND = 19,       /* name or id not found */
  SMG_ERROR_PARSE = 20,           /* malformed input file (offline tools) */
  SMG_ERROR_UNSUPPORTED = 21,     /* valid request this build cannot do */
  SMG_RESULT_FORCE_32 = 0x7fffffff
} smg_result;

/* A static, human-readable name for a result ("SMG_OK",
 * "SMG_ERROR_BLOB_CHECKSUM: payload checksum mismatch", ...). Never NULL;
 * unknown values give "SMG_ERROR_UNKNOWN". */
SMG_API const char* smg_result_string(smg_result result);

/* ------------------------------------------------------------------------ */
/* Hooks: memory and logging                                                */
/* ------------------------------------------------------------------------ */

/* Route libsmg's memory through the engine. Both functions set, or both
 * NULL for malloc/free. alloc must return memory aligned to at least
 * `align` (a power of two <= 64) or NULL on failure. */
typedef struct smg_allocator {
  void* (*alloc)(size_t size, size_t align, void* user);
  void (*free)(void* ptr, void* user);
  void* user;
} smg_allocator;

#define SMG_LOG_ERROR 1u
#define SMG_LOG_WARNING 2u
#define SMG_LOG_INFO 3u

/* Optional: receives one line (no trailing newline) explaining failures,
 * e.g. which section and index of a blob is bad. NULL func: silent. */
typedef struct smg_logger {
  void (*func)(uint32_t level, const char* message, void* user);
  void* user;
} smg_logger;

/* ------------------------------------------------------------------------ */
/* Graph: the immutable, shareable result of baking                         */
/* ------------------------------------------------------------------------ */

typedef struct smg_graph smg_graph;

/* Load flags. */
#define SMG_GRAPH_SKIP_CHECKSUM 1u /* trust the bytes (faster load); every
                                      structural check still runs */

typedef struct smg_graph_desc {
  uint32_t struct_size; /* = sizeof(smg_graph_desc) */
  uint32_t flags;       /* SMG_GRAPH_* flags; 0 = full validation */
  smg_allocator allocator;
  smg_logger logger;
} smg_graph_desc;

/* Read and validate a blob file. desc may be NULL (all defaults). */
SMG_API smg_result smg_graph_load_file(const char* path,
                                       const smg_graph_desc* desc,
                                       smg_graph** out_graph);

/* Validate a blob in caller-owned memory and use it in place (no copy).
 * `data` must be 16-byte aligned and must stay alive and unchanged until
 * smg_graph_destroy(). */
SMG_API smg_result smg_graph_load_memory(const void* data, size_t size,
                                         const smg_graph_desc* desc,
                                         smg_graph** out_graph);

/* Free a graph. Fails with SMG_ERROR_IN_USE while characters exist. */
SMG_API smg_result smg_graph_destroy(smg_graph* graph);

typedef struct smg_graph_info {
  uint32_t struct_size;     /* caller sets = sizeof(smg_graph_info) */
  uint32_t format_version;  /* blob format version */
  uint32_t joint_count;     /* skeleton joints (31 for the CMU set) */
  uint32_t style_count;     /* locomotion styles, e.g. walk, run */
  uint32_t action_count;    /* upper-body actions; action 0 is "none" */
  uint32_t frame_count;     /* frames in the pool (clips + transitions) */
  uint32_t lower_node_count, lower_edge_count;
  uint32_t upper_node_count, upper_edge_count;
  uint32_t splice_count;    /* splice candidates */
  uint32_t character_count; /* live characters using this graph */
  float frame_rate;         /* frames per second of the pool */
  float reserved0;
  uint64_t blob_size;       /* bytes */
} smg_graph_info;

SMG_API smg_result smg_graph_get_info(const smg_graph* graph,
                                      smg_graph_info* out_info);

#define SMG_NO_PARENT (-1)

typedef struct smg_joint_info {
  uint32_t struct_size; /* caller sets = sizeof(smg_joint_info) */
  int32_t parent;       /* SMG_NO_PARENT for the root (joint 0) */
  const char* name;     /* valid while the graph lives */
  float rest_offset[3]; /* offset from the parent joint, metres */
  uint32_t body_part;   /* SMG_BODY_ROOT, SMG_BODY_LOWER, SMG_BODY_UPPER */
} smg_joint_info;

#define SMG_BODY_ROOT 0u
#define SMG_BODY_LOWER 1u
#define SMG_BODY_UPPER 2u

SMG_API smg_result smg_graph_get_joint(const smg_graph* graph, uint32_t index,
                                       smg_joint_info* out_joint);
SMG_API smg_result smg_graph_find_joint(const smg_graph* graph,
                                        const char* name, uint32_t* out_index);

/* Styles (lower body: "walk", "run", ...) and actions (upper body: "none",
 * "punch", ...). Names stay valid while the graph lives. */
SMG_API smg_result smg_graph_get_style_name(const smg_graph* graph,
                                            uint32_t style,
                                            const char** out_name);
SMG_API smg_result smg_graph_find_style(const smg_graph* graph,
                                        const char* name, uint32_t* out_style);
SMG_API smg_result smg_graph_get_action_name(const smg_graph* graph,
                                             uint32_t action,
                                             const char** out_name);
SMG_API smg_result smg_graph_find_action(const smg_graph* graph,
                                         const char* name,
                                         uint32_t* out_action);

/* ------------------------------------------------------------------------ */
/* Character: one animated figure following one path                        */
/* ------------------------------------------------------------------------ */

typedef struct smg_character smg_character;

/* Character flags (other bits: SMG_ERROR_INVALID_ARGUMENT). */
#define SMG_CHARACTER_NO_IK 1u /* start with foot-contact IK off */
#define SMG_CHARACTER_NO_STEERING 2u /* start with root steering off: the
                                        motion graph alone (see below) */
#define SMG_CHARACTER_NO_SWING_CLEARANCE 4u /* swinging feet as the data
                                               has them (see below) */

typedef struct smg_character_desc {
  uint32_t struct_size;      /* = sizeof(smg_character_desc) */
  uint32_t flags;            /* SMG_CHARACTER_* */
  uint32_t initial_style;    /* style index (0 = first style) */
  uint32_t initial_action;   /* action index (0 = "none") */
  uint32_t path_capacity;    /* max path points; 0 = 512 */
  uint32_t constraint_capacity; /* max transition+splice points; 0 = 32 */
  uint32_t seed;             /* varies choices among equal options and,
                                with the start position, which frames the
                                character searches in; 0 ok */
  uint32_t reserved0;
  float position[3];         /* start position; y is ignored (ground) */
  float heading;             /* start heading, radians */
  float horizon;             /* planning look-ahead, seconds; 0 = 2.0.
                                While root steering follows a path, at
                                most 1 s is kept planned (the steering
                                re-plans as its correction adds up); the
                                full horizon returns near the path's end */
  float error_threshold;     /* search distance-error threshold, metres;
                                0 = 0.25 */
  smg_allocator allocator;   /* 0 = malloc/free */
  /* Root steering (on unless SMG_CHARACTER_NO_STEERING): every step a
   * small, bounded correction of the character's ground position and
   * heading keeps the motion on the path (the data need not turn as
   * tightly as the path), slows it where the path is too tight, and brings
   * it to rest at the path's end (docs/runtime.md, "Root steering"). The
   * correction is reported in smg_character_state. Zero = default. */
  float steer_turn_rate;     /* most heading correction added to the
                                motion's own turning, radians per second
                                (twice this while cutting a hairpin: a
                                pivot over the planted foot); 0 = 3.0
                                (about 170 deg/s) */
  float steer_slide_ratio;   /* most translation correction, as a fraction
                                of the motion's own ground speed (none
                                while it stands); 0 = 0.25 */
  float stop_seconds;        /* braking time when coming to rest at the
                                path's end; 0 = 1.0. Maxima:
                                SMG_MAX_STEER_TURN_RATE,
                                SMG_MAX_STEER_SLIDE_RATIO,
                                SMG_MAX_STOP_SECONDS */
  /* Swing clearance (part of the foot IK; off with SMG_CHARACTER_NO_IK or
   * SMG_CHARACTER_NO_SWING_CLEARANCE): a foot swinging fast keeps its toe
   * at least this high above the floor that foot last stood on, so it
   * never brushes along the ground - it would read as a sliding foot, and
   * a shoe mesh thicker than the performer's foot would cut into the
   * floor. Feet that stand, land or push off are not touched
   * (docs/runtime.md, "Foot IK"). */
  float swing_clearance;     /* metres, at most SMG_MAX_SWING_CLEARANCE;
                                0 = 0.04 leg lengths (about 3.5 cm on an
                                adult) */
} smg_character_desc;

/* The largest swing clearance accepted, metres (more only stretches the
 * leg; larger or negative values give SMG_ERROR_INVALID_ARGUMENT). */
#define SMG_MAX_SWING_CLEARANCE 0.5f

/* Create a character on `graph`. desc may be NULL (all defaults). Allocates
 * every byte the character will ever need. */
SMG_API smg_result smg_character_create(smg_graph* graph,
                                        const smg_character_desc* desc,
                                        smg_character** out_character);
SMG_API smg_result smg_character_destroy(smg_character* character);

/* Bytes smg_character_create() would allocate for this desc (for budgets). */
SMG_API smg_result smg_character_memory_size(const smg_graph* graph,
                                             const smg_character_desc* desc,
                                             size_t* out_bytes);

/* --- The path: a polyline on the ground, given as interleaved (x, z). ---
 * Ground coordinates (path points, the start position) must be finite and
 * smaller than SMG_MAX_COORDINATE in magnitude (beyond 2^20 m a float's
 * spacing exceeds 6 cm and lengths lose their meaning); others give
 * SMG_ERROR_INVALID_ARGUMENT. */
#define SMG_MAX_COORDINATE 1048576.0f

/* Replace the path. The character keeps its committed motion and rejoins
 * the new path from where it is (distance along the new path restarts at
 * the point nearest the character). Constraints are kept; those beyond the
 * new end wait until the path grows past them. count 0 clears the path. */
SMG_API smg_result smg_character_set_path(smg_character* character,
                                          const float* xz, uint32_t count);
/* Append points while the user is still drawing. */
SMG_API smg_result smg_character_append_path(smg_character* character,
                                             const float* xz, uint32_t count);
/* Remove the path: the character comes to a stop along committed motion. */
SMG_API smg_result smg_character_clear_path(smg_character* character);
/* Total arc length of the current path, metres. */
SMG_API smg_result smg_character_get_path_length(
    const smg_character* character, float* out_length);

/* --- Constraints at arc lengths along the path (ids are > 0). ---
 * arc_length is metres from the path's first point and must lie within the
 * current path, [0, smg_character_get_path_length()]; beyond the end, add
 * and move return SMG_ERROR_OUT_OF_RANGE (place points along a path that is
 * still being drawn once it has grown past them). Style/action indices not
 * in the graph give SMG_ERROR_UNKNOWN_STYLE / SMG_ERROR_UNKNOWN_ACTION. */

/* From `arc_length` on, the lower body uses locomotion `style`. */
SMG_API smg_result smg_character_add_transition(smg_character* character,
                                                float arc_length,
                                                uint32_t style,
                                                uint32_t* out_id);
/* From `arc_length` on, the upper body does `action` (0 = "none": the
 * locomotion's own upper body). */
SMG_API smg_result smg_character_add_splice(smg_character* character,
                                            float arc_length, uint32_t action,
                                            uint32_t* out_id);
SMG_API smg_result smg_character_move_constraint(smg_character* character,
                                                 uint32_t id,
                                                 float arc_length);
SMG_API smg_result smg_character_remove_constraint(smg_character* character,
                                                   uint32_t id);
SMG_API smg_result smg_character_clear_constraints(smg_character* character);

/* --- Immediate controls --- */

/* Switch style/action as soon as possible (like a constraint at the
 * character's current distance along the path). */
SMG_API smg_result smg_character_set_style(smg_character* character,
                                           uint32_t style);
SMG_API smg_result smg_character_set_action(smg_character* character,
                                            uint32_t action);
SMG_API smg_result smg_character_set_error_threshold(smg_character* character,
                                                     float metres);
SMG_API smg_result smg_character_set_ik(smg_character* character,
                                        uint32_t enabled);
/* Root steering on (1) or off (0); off gives the motion graph alone, as
 * SMG_CHARACTER_NO_STEERING at create. Takes effect at the next step. */
SMG_API smg_result smg_character_set_steering(smg_character* character,
                                              uint32_t enabled);
/* The steering limits of smg_character_desc (turn rate rad/s, slide ratio,
 * stop seconds; 0 = default). A negative or non-finite value, or one above
 * its maximum below, returns SMG_ERROR_INVALID_ARGUMENT and changes
 * nothing. */
#define SMG_MAX_STEER_TURN_RATE 12.0f  /* rad/s (about 690 deg/s) */
#define SMG_MAX_STEER_SLIDE_RATIO 1.0f /* the motion's own speed */
#define SMG_MAX_STOP_SECONDS 60.0f
SMG_API smg_result smg_character_set_steering_limits(smg_character* character,
                                                     float turn_rate,
                                                     float slide_ratio,
                                                     float stop_seconds);
/* Swing clearance on (1) or off (0), and the clearance in metres (0 = the
 * default, 0.04 leg lengths): as SMG_CHARACTER_NO_SWING_CLEARANCE and
 * smg_character_desc.swing_clearance at create. A negative, non-finite or
 * too large (SMG_MAX_SWING_CLEARANCE) clearance returns
 * SMG_ERROR_INVALID_ARGUMENT and changes nothing. A lift
 * in progress moves to the new clearance at its bounded rate. */
SMG_API smg_result smg_character_set_swing_clearance(smg_character* character,
                                                     uint32_t enabled,
                                                     float clearance);

/* --- Per frame --- */

/* Advance by dt seconds (0 <= dt <= 1; 0 is allowed and does nothing).
 * Bounded work, no allocation. */
SMG_API smg_result smg_character_step(smg_character* character, float dt);

/* State flags. */
#define SMG_STATE_HAS_PATH 1u        /* a path with >= 1 point is set */
#define SMG_STATE_PATH_END_REACHED 2u /* arrived at the path's end (with
                                         steering: standing there) */
#define SMG_STATE_LEFT_CONTACT 4u     /* left foot planted this frame */
#define SMG_STATE_RIGHT_CONTACT 8u    /* right foot planted this frame */

typedef struct smg_character_state {
  uint32_t struct_size;  /* caller sets = sizeof(smg_character_state) */
  uint32_t flags;        /* SMG_STATE_* */
  uint32_t style;        /* current lower-body style */
  uint32_t action;       /* current upper-body action */
  float position[3];     /* root projected on the ground (y: the ground
                            height there, 0 unless smg_character_set_ground
                            or _set_ground_position gave one) */
  float heading;         /* facing, radians */
  float path_distance;   /* arc length travelled along the current path */
  float path_error;      /* current distance of the root from the path */
  double time;           /* seconds stepped since creation */
  uint32_t lower_node;   /* diagnostics: last lower-graph node passed */
  uint32_t upper_node;   /* diagnostics: last upper-graph node passed */
  float sync_rate;       /* upper-body playback rate vs lower (1 = none) */
  float reserved0;
  /* the root steering's correction in the last step (0 with it off) */
  float steer_turn_rate;   /* heading added, radians/s (+ = to the left) */
  float steer_slide_speed; /* translation added, m/s */
  float playback_rate;     /* how fast the motion plays: 1, lower while
                              slowing for a tight turn or braking, 0 at
                              rest */
  float reserved1;
} smg_character_state;

SMG_API smg_result smg_character_get_state(const smg_character* character,
                                           smg_character_state* out_state);

/* Joint-local pose: root_translation (3 floats) is the world position of
 * joint 0; rotations (4 * joint_count floats) are local to each parent,
 * joint 0's is its world rotation. joint_count must equal the graph's. */
SMG_API smg_result smg_character_get_local_pose(
    const smg_character* character, float* root_translation,
    float* rotations, uint32_t joint_count);

#define SMG_SPACE_WORLD 0u     /* matrices include the character's motion */
#define SMG_SPACE_CHARACTER 1u /* relative to (position, heading) in state */

/* Model-space joint matrices (16 * joint_count floats, column-major), for
 * skinning multiply by the inverse bind matrices yourself. */
SMG_API smg_result smg_character_get_model_matrices(
    const smg_character* character, uint32_t space, float* matrices,
    uint32_t joint_count);

/* --- Events: what happened in the last step (docs/api-guide.md,
 * "Events"). Read after smg_character_step; each step replaces them. --- */

#define SMG_EVENT_CONSTRAINT 1u /* a transition or splice took effect */
#define SMG_EVENT_FOOTSTEP 2u   /* a foot landed */
#define SMG_EVENT_PATH_END 3u   /* arrived at the path's end */

/* smg_event.flags */
#define SMG_EVENT_SPLICE 1u     /* CONSTRAINT: an action (else a style) */
#define SMG_EVENT_SUPERSEDED 2u /* CONSTRAINT: will never take effect: a
                                   later one of its kind (or set_style /
                                   set_action) took over first */
#define SMG_EVENT_UNCHANGED 4u  /* CONSTRAINT: reached while its style or
                                   action was already shown */

typedef struct smg_event {
  uint32_t struct_size; /* events[0].struct_size = sizeof(smg_event): the
                           element size of the caller's array */
  uint32_t type;        /* SMG_EVENT_* */
  uint32_t id;          /* CONSTRAINT: the id add_transition/_add_splice
                           returned; 0 for a change no constraint asked
                           for (set_style/set_action, the steering walking
                           to a stop). FOOTSTEP: 0 left, 1 right */
  uint32_t value;       /* CONSTRAINT: its style or action */
  uint32_t flags;       /* SMG_EVENT_SPLICE, _SUPERSEDED, _UNCHANGED */
  float position[3];    /* FOOTSTEP: the toe where it landed (world);
                           others: the character's ground position */
  float strength;       /* FOOTSTEP: the toe's downward speed over about
                           the last 0.1 s of its descent, m/s (how hard
                           it landed); 0 for other events */
  float arc_length;     /* path distance of the character at that step */
  uint32_t reserved0, reserved1;
} smg_event;

/* The events of the last step, in the order they happened within it.
 * Every constraint gives exactly one CONSTRAINT event: at the step whose
 * frame first shows its style or action, or flagged UNCHANGED /
 * SUPERSEDED; a removed one gives none. The queue holds
 * constraint_capacity + 5 events, enough for any step.
 * events NULL and capacity 0: *out_count = how many there are. With
 * capacity below the count: SMG_ERROR_BUFFER_TOO_SMALL, *out_count = the
 * count, nothing written. */
SMG_API smg_result smg_character_get_events(const smg_character* character,
                                            smg_event* events,
                                            uint32_t capacity,
                                            uint32_t* out_count);

/* --- Root motion for the engine's mover (docs/api-guide.md, "Root
 * motion"). --- */

typedef struct smg_root_motion {
  uint32_t struct_size;       /* caller sets = sizeof(smg_root_motion) */
  uint32_t flags;             /* 0 (reserved) */
  float translation[3];       /* world displacement of the ground position
                                 over the last step, metres (y: the change
                                 of the ground height under it) */
  float yaw;                  /* heading change, radians (+ = left) */
  float local_translation[3]; /* the same displacement in the character's
                                 frame at the start of the step (x: left,
                                 y: up, z: forward, as heading 0 faces +Z) */
  float reserved0;
} smg_root_motion;

SMG_API smg_result smg_character_get_root_motion(
    const smg_character* character, smg_root_motion* out_motion);

/* Where the engine's mover put the character after the last step (its
 * collisions): ground position (y = the floor height there) and heading.
 * The character's committed motion, plan, steering and planted feet move
 * with it rigidly - the pose in character space does not change, nothing
 * pops - and steering and planning go on from there back to the path.
 * Finite, |x| and |z| below SMG_MAX_COORDINATE, |y| below it too. */
SMG_API smg_result smg_character_set_ground_position(
    smg_character* character, const float* position, float heading);

/* --- Uneven ground (docs/api-guide.md, "Uneven ground"): heights the
 * engine measures before each step; nothing is called back. --- */

typedef struct smg_ground {
  uint32_t struct_size;  /* caller sets = sizeof(smg_ground) */
  uint32_t flags;        /* 0 (reserved) */
  float foot_height[2];  /* ground height (world y) at the left and right
                            probes of smg_character_get_ground_probes */
  float root_height;     /* ground height at the root probe */
  float reserved0;
} smg_ground;

/* Where to measure the ground for the next step: `count` (= 3) points
 * (x, z) in xz - left foot, right foot, root - where they are expected:
 * a planted foot's toe, a swinging toe carried on by its speed, the ground
 * position carried on by the character's. */
SMG_API smg_result smg_character_get_ground_probes(
    const smg_character* character, float* xz, uint32_t count);

/* The ground for the next steps, measured at the probes; NULL: flat at
 * y = 0 again (the default). Heights finite, below SMG_MAX_COORDINATE in
 * magnitude. Planted toes are held on their heights, the pelvis lowers
 * where a leg could not reach, and the root follows root_height. */
SMG_API smg_result smg_character_set_ground(smg_character* character,
                                            const smg_ground* ground);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* SMG_H */
