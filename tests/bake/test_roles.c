/*
 * test_roles.c - body roles (libsmg/bake/bake_roles.c): every naming
 * convention the baker promises to recognise, written out here as tables of
 * joint names on one 21-joint humanoid topology; left/right counterparts
 * for each convention; the `bones` override; errors that name the source
 * and the role.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "bake_roles.h"
#include "import_helpers.h"

/* Topology shared by every convention: parent of each template joint. */
#define TJ 21
static const int32_t k_parent[TJ] = {-1, 0, 1, 2, 3,       /* pelvis..head */
                                     2,  5, 6, 7,          /* left arm */
                                     2,  9, 10, 11,        /* right arm */
                                     0,  13, 14, 15,       /* left leg */
                                     0,  17, 18, 19};      /* right leg */
/* Role of each template joint (-1: none: the chest). */
static const int k_role[TJ] = {
    SMGB_ROLE_PELVIS,          SMGB_ROLE_SPINE_BASE,      -1,
    SMGB_ROLE_NECK,            SMGB_ROLE_HEAD,            SMGB_ROLE_LEFT_SHOULDER,
    SMGB_ROLE_LEFT_UPPER_ARM,  SMGB_ROLE_LEFT_LOWER_ARM,  SMGB_ROLE_LEFT_HAND,
    SMGB_ROLE_RIGHT_SHOULDER,  SMGB_ROLE_RIGHT_UPPER_ARM, SMGB_ROLE_RIGHT_LOWER_ARM,
    SMGB_ROLE_RIGHT_HAND,      SMGB_ROLE_LEFT_UPPER_LEG,  SMGB_ROLE_LEFT_LOWER_LEG,
    SMGB_ROLE_LEFT_FOOT,       SMGB_ROLE_LEFT_TOES,       SMGB_ROLE_RIGHT_UPPER_LEG,
    SMGB_ROLE_RIGHT_LOWER_LEG, SMGB_ROLE_RIGHT_FOOT,      SMGB_ROLE_RIGHT_TOES};
/* Template joint of each joint's left/right counterpart. */
static const int k_mirror[TJ] = {0,  1,  2,  3,  4,  9,  10, 11, 12, 5, 6,
                                 7,  8,  17, 18, 19, 20, 13, 14, 15, 16};

typedef struct convention {
  const char* what;
  const char* names[TJ];
} convention;

static const convention k_conventions[] = {
    {"CMU / Mixamo without namespace",
     {"Hips", "Spine", "Spine1", "Neck", "Head", "LeftShoulder", "LeftArm",
      "LeftForeArm", "LeftHand", "RightShoulder", "RightArm", "RightForeArm",
      "RightHand", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase",
      "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase"}},
    {"Bandai Namco",
     {"Hips", "Spine", "Chest", "Neck", "Head", "Shoulder_L", "UpperArm_L",
      "LowerArm_L", "Hand_L", "Shoulder_R", "UpperArm_R", "LowerArm_R",
      "Hand_R", "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L", "UpperLeg_R",
      "LowerLeg_R", "Foot_R", "Toes_R"}},
    {"Mixamo",
     {"mixamorig:Hips", "mixamorig:Spine", "mixamorig:Spine1",
      "mixamorig:Neck", "mixamorig:Head", "mixamorig:LeftShoulder",
      "mixamorig:LeftArm", "mixamorig:LeftForeArm", "mixamorig:LeftHand",
      "mixamorig:RightShoulder", "mixamorig:RightArm",
      "mixamorig:RightForeArm", "mixamorig:RightHand", "mixamorig:LeftUpLeg",
      "mixamorig:LeftLeg", "mixamorig:LeftFoot", "mixamorig:LeftToeBase",
      "mixamorig:RightUpLeg", "mixamorig:RightLeg", "mixamorig:RightFoot",
      "mixamorig:RightToeBase"}},
    {"Godot SkeletonProfileHumanoid / Unity HumanBodyBones",
     {"Hips", "Spine", "Chest", "Neck", "Head", "LeftShoulder",
      "LeftUpperArm", "LeftLowerArm", "LeftHand", "RightShoulder",
      "RightUpperArm", "RightLowerArm", "RightHand", "LeftUpperLeg",
      "LeftLowerLeg", "LeftFoot", "LeftToes", "RightUpperLeg",
      "RightLowerLeg", "RightFoot", "RightToes"}},
    {"VRM humanoid",
     {"hips", "spine", "chest", "neck", "head", "leftShoulder",
      "leftUpperArm", "leftLowerArm", "leftHand", "rightShoulder",
      "rightUpperArm", "rightLowerArm", "rightHand", "leftUpperLeg",
      "leftLowerLeg", "leftFoot", "leftToes", "rightUpperLeg",
      "rightLowerLeg", "rightFoot", "rightToes"}},
    {"Unreal",
     {"pelvis", "spine_01", "spine_02", "neck_01", "head", "clavicle_l",
      "upperarm_l", "lowerarm_l", "hand_l", "clavicle_r", "upperarm_r",
      "lowerarm_r", "hand_r", "thigh_l", "calf_l", "foot_l", "ball_l",
      "thigh_r", "calf_r", "foot_r", "ball_r"}},
    {"Blender .L/.R (pelvis found structurally)",
     {"torso", "spine", "spine.001", "neck", "head", "shoulder.L",
      "upper_arm.L", "forearm.L", "hand.L", "shoulder.R", "upper_arm.R",
      "forearm.R", "hand.R", "thigh.L", "shin.L", "foot.L", "toe.L",
      "thigh.R", "shin.R", "foot.R", "toe.R"}},
    {"VRoid VRM export",
     {"J_Bip_C_Hips", "J_Bip_C_Spine", "J_Bip_C_Chest", "J_Bip_C_Neck",
      "J_Bip_C_Head", "J_Bip_L_Shoulder", "J_Bip_L_UpperArm",
      "J_Bip_L_LowerArm", "J_Bip_L_Hand", "J_Bip_R_Shoulder",
      "J_Bip_R_UpperArm", "J_Bip_R_LowerArm", "J_Bip_R_Hand",
      "J_Bip_L_UpperLeg", "J_Bip_L_LowerLeg", "J_Bip_L_Foot",
      "J_Bip_L_ToeBase", "J_Bip_R_UpperLeg", "J_Bip_R_LowerLeg",
      "J_Bip_R_Foot", "J_Bip_R_ToeBase"}},
    {"MotionBuilder HumanIK",
     {"Character1_Hips", "Character1_Spine", "Character1_Spine1",
      "Character1_Neck", "Character1_Head", "Character1_LeftShoulder",
      "Character1_LeftArm", "Character1_LeftForeArm", "Character1_LeftHand",
      "Character1_RightShoulder", "Character1_RightArm",
      "Character1_RightForeArm", "Character1_RightHand",
      "Character1_LeftUpLeg", "Character1_LeftLeg", "Character1_LeftFoot",
      "Character1_LeftToeBase", "Character1_RightUpLeg",
      "Character1_RightLeg", "Character1_RightFoot",
      "Character1_RightToeBase"}},
    {"Rigify deform bones",
     {"DEF-pelvis", "DEF-spine", "DEF-spine.001", "DEF-neck", "DEF-head",
      "DEF-shoulder.L", "DEF-upper_arm.L", "DEF-forearm.L", "DEF-hand.L",
      "DEF-shoulder.R", "DEF-upper_arm.R", "DEF-forearm.R", "DEF-hand.R",
      "DEF-thigh.L", "DEF-shin.L", "DEF-foot.L", "DEF-toe.L", "DEF-thigh.R",
      "DEF-shin.R", "DEF-foot.R", "DEF-toe.R"}},
    {"3ds Max Biped",
     {"Bip01 Pelvis", "Bip01 Spine", "Bip01 Spine1", "Bip01 Neck",
      "Bip01 Head", "Bip01 L Clavicle", "Bip01 L UpperArm",
      "Bip01 L Forearm", "Bip01 L Hand", "Bip01 R Clavicle",
      "Bip01 R UpperArm", "Bip01 R Forearm", "Bip01 R Hand",
      "Bip01 L Thigh", "Bip01 L Calf", "Bip01 L Foot", "Bip01 L Toe0",
      "Bip01 R Thigh", "Bip01 R Calf", "Bip01 R Foot", "Bip01 R Toe0"}},
};

typedef struct test_skel {
  char names[TJ][SMGB_NAME_MAX];
  int32_t parents[TJ];
  float offsets[TJ][3];
  smgb_skeleton s;
} test_skel;

/* The template with `names`; legs 0.45 + 0.42 m long. */
static void make_skel(test_skel* t, const char* const* names) {
  int j;
  memset(t, 0, sizeof *t);
  for (j = 0; j < TJ; ++j) {
    snprintf(t->names[j], SMGB_NAME_MAX, "%s", names[j]);
    t->parents[j] = k_parent[j];
    t->offsets[j][1] = 0.1f;
  }
  t->offsets[13][0] = 0.1f;
  t->offsets[17][0] = -0.1f;
  t->offsets[14][1] = t->offsets[18][1] = -0.45f;
  t->offsets[15][1] = t->offsets[19][1] = -0.42f;
  t->s.joint_count = TJ;
  t->s.names = t->names;
  t->s.parents = t->parents;
  t->s.offsets = t->offsets;
}

static void test_conventions(void** state) {
  size_t c;
  (void)state;
  for (c = 0; c < sizeof k_conventions / sizeof k_conventions[0]; ++c) {
    test_skel t;
    smgb_roles r;
    smgb_error err;
    int j, k;
    make_skel(&t, k_conventions[c].names);
    if (smgb_roles_find(&t.s, NULL, "conv.bvh", &r, &err) != SMG_OK)
      fail_msg("%s: %s", k_conventions[c].what, err.message);
    for (j = 0; j < TJ; ++j) {
      if (k_role[j] < 0) continue;
      if (r.joint[k_role[j]] != j)
        fail_msg("%s: role %s is joint %d, want %d (%s)",
                 k_conventions[c].what, smgb_role_name((smgb_role)k_role[j]),
                 (int)r.joint[k_role[j]], j, t.names[j]);
    }
    /* No joint plays two roles; the fingers are absent. */
    for (k = 0; k < SMGB_ROLE_COUNT; ++k)
      for (j = k + 1; j < SMGB_ROLE_COUNT; ++j)
        if (r.joint[k] >= 0) assert_int_not_equal(r.joint[k], r.joint[j]);
    assert_int_equal(r.joint[SMGB_ROLE_LEFT_FINGERS], -1);
    assert_float_equal(smgb_roles_leg_length(&t.s, &r), 0.87f, 1e-5f);
    assert_float_equal(smgb_skeleton_leg_length(&t.s), 0.87f, 1e-5f);
  }
}

static void test_counterparts(void** state) {
  size_t c;
  (void)state;
  for (c = 0; c < sizeof k_conventions / sizeof k_conventions[0]; ++c) {
    int j;
    for (j = 0; j < TJ; ++j) {
      const char* n = k_conventions[c].names[j];
      const char* want = k_conventions[c].names[k_mirror[j]];
      char out[SMGB_NAME_MAX], back[SMGB_NAME_MAX];
      int sided = smgb_roles_counterpart_name(n, out);
      if (k_mirror[j] == j) {
        if (sided) fail_msg("%s: '%s' has no side, got '%s'",
                            k_conventions[c].what, n, out);
        continue;
      }
      if (!sided || strcmp(out, want) != 0)
        fail_msg("%s: counterpart of '%s' is '%s', want '%s'",
                 k_conventions[c].what, n, sided ? out : "(none)", want);
      assert_true(smgb_roles_counterpart_name(out, back));
      assert_string_equal(back, n);
    }
  }
  /* CMU helpers and case forms. */
  {
    static const char* const pairs[][2] = {
        {"LHipJoint", "RHipJoint"}, {"LThumb", "RThumb"},
        {"LeftHandIndex1", "RightHandIndex1"}, {"HipLeft", "HipRight"},
        {"LEFT_ARM", "RIGHT_ARM"}, {"l_hip", "r_hip"},
        {"mixamorig:LeftToe_End", "mixamorig:RightToe_End"}};
    size_t i;
    char out[SMGB_NAME_MAX];
    for (i = 0; i < sizeof pairs / sizeof pairs[0]; ++i) {
      assert_true(smgb_roles_counterpart_name(pairs[i][0], out));
      assert_string_equal(out, pairs[i][1]);
    }
    assert_false(smgb_roles_counterpart_name("LowerBack", out));
    assert_false(smgb_roles_counterpart_name("Lhand", out));
    assert_false(smgb_roles_counterpart_name("joint_Root", out));
  }
}

/* CMU's real layout: a zero-length LHipJoint above LeftUpLeg, LowerBack
 * as the spine base, Neck and Neck1, finger joints. */
static void test_cmu_layout(void** state) {
  static const char* const names[] = {
      "Hips", "LHipJoint", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase",
      "RHipJoint", "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase",
      "LowerBack", "Spine", "Spine1", "Neck", "Neck1", "Head",
      "LeftShoulder", "LeftArm", "LeftForeArm", "LeftHand", "LeftFingerBase",
      "LeftHandIndex1", "LThumb", "RightShoulder", "RightArm", "RightForeArm",
      "RightHand", "RightFingerBase", "RightHandIndex1", "RThumb"};
  static const int32_t parents[] = {-1, 0, 1, 2, 3, 4, 0, 6, 7, 8, 9,
                                    0, 11, 12, 13, 14, 15, 13, 17, 18, 19, 20,
                                    21, 20, 13, 24, 25, 26, 27, 28, 27};
  char nm[31][SMGB_NAME_MAX];
  int32_t par[31];
  float off[31][3];
  smgb_skeleton s;
  smgb_roles r;
  smgb_error err;
  int j;
  (void)state;
  for (j = 0; j < 31; ++j) {
    snprintf(nm[j], SMGB_NAME_MAX, "%s", names[j]);
    par[j] = parents[j];
    off[j][0] = 0.0f;
    off[j][1] = j == 1 || j == 6 || j == 11 ? 0.0f : 0.1f;
    off[j][2] = 0.0f;
  }
  s.joint_count = 31;
  s.names = nm;
  s.parents = par;
  s.offsets = off;
  assert_int_equal(smgb_roles_find(&s, NULL, "cmu.bvh", &r, &err), SMG_OK);
  assert_int_equal(r.joint[SMGB_ROLE_PELVIS], 0);
  assert_int_equal(r.joint[SMGB_ROLE_SPINE_BASE], 11);  /* LowerBack */
  assert_int_equal(r.joint[SMGB_ROLE_NECK], 14);        /* Neck, not Neck1 */
  assert_int_equal(r.joint[SMGB_ROLE_LEFT_UPPER_LEG], 2);
  assert_int_equal(r.joint[SMGB_ROLE_RIGHT_TOES], 10);
  assert_int_equal(r.joint[SMGB_ROLE_LEFT_FINGERS], 22); /* HandIndex1 */
  assert_int_equal(r.joint[SMGB_ROLE_RIGHT_SHOULDER], 24);
}

/* Names no convention knows, mapped with a bone map. */
static void test_bone_map(void** state) {
  static const char* const odd[TJ] = {
      "J00", "J01", "J02", "J03", "J04", "J05", "J06", "J07", "J08", "J09",
      "J10", "J11", "J12", "J13", "J14", "J15", "J16", "J17", "J18", "J19",
      "J20"};
  static const char map[] =
      "pelvis=J00\nneck=J03\nhead=J04\n"
      "left_upper_arm=J06\nleft_lower_arm=J07\nleft_hand=J08\n"
      "right_upper_arm=J10\nright_lower_arm=J11\nright_hand=J12\n"
      "left_upper_leg=J13\nleft_lower_leg=J14\nleft_foot=J15\n"
      "left_toes = J16 \n right_upper_leg=J17\nright_lower_leg=J18\n"
      "right_foot=J19\nright_toes=J20\n";
  test_skel t;
  smgb_roles r;
  smgb_error err;
  int j;
  (void)state;
  make_skel(&t, odd);
  /* Without the map: the error names the file and the first role. */
  assert_int_equal(smgb_roles_find(&t.s, NULL, "odd.bvh", &r, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "odd.bvh"));
  assert_non_null(strstr(err.message, "'neck'"));
  assert_non_null(strstr(err.message, "bones neck=JOINT"));
  assert_int_equal(smgb_roles_find(&t.s, map, "odd.bvh", &r, &err), SMG_OK);
  for (j = 0; j < TJ; ++j)
    if (k_role[j] >= 0 && k_role[j] < SMGB_ROLE_REQUIRED_COUNT)
      assert_int_equal(r.joint[k_role[j]], j);
  assert_int_equal(r.joint[SMGB_ROLE_SPINE_BASE], 1); /* structural */

  /* The map overrides recognised names, but a limb must stay in order. */
  make_skel(&t, k_conventions[3].names);
  assert_int_equal(smgb_roles_find(&t.s, "left_toes=LeftFoot", "godot.glb", &r,
                                   &err),
                   SMG_ERROR_INVALID_ARGUMENT); /* toes not below the foot */
  assert_non_null(strstr(err.message, "left_toes"));
  assert_int_equal(smgb_roles_find(&t.s, "head=Neck", "godot.glb", &r, &err),
                   SMG_OK);
  assert_int_equal(r.joint[SMGB_ROLE_HEAD], 3);

  /* A map naming a missing joint: file, role and joint in the message. */
  assert_int_equal(smgb_roles_find(&t.s, "left_foot=Foot_L", "godot.glb", &r,
                                   &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "godot.glb"));
  assert_non_null(strstr(err.message, "left_foot"));
  assert_non_null(strstr(err.message, "'Foot_L'"));
  /* Syntax and unknown roles. */
  assert_int_equal(smgb_bone_map_check("left_foot=A\nright_foot=B", "m", &err),
                   SMG_OK);
  assert_int_equal(smgb_bone_map_check("left_foot", "m", &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_int_equal(smgb_bone_map_check("left_paw=A", "m", &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "left_paw"));
  assert_int_equal(smgb_bone_map_check(NULL, "m", &err), SMG_OK);
}

/* A skeleton without legs: the error names the file and a leg role. */
static void test_no_legs(void** state) {
  test_skel t;
  smgb_roles r;
  smgb_error err;
  int j;
  (void)state;
  make_skel(&t, k_conventions[0].names);
  for (j = 13; j < TJ; ++j) snprintf(t.names[j], SMGB_NAME_MAX, "Tail%d", j);
  assert_int_equal(smgb_roles_find(&t.s, NULL, "tail.bvh", &r, &err),
                   SMG_ERROR_INVALID_ARGUMENT);
  assert_non_null(strstr(err.message, "tail.bvh"));
  assert_non_null(strstr(err.message, "upper_leg"));
  smgb_roles_guess(&t.s, &r);
  assert_int_equal(r.joint[SMGB_ROLE_LEFT_FOOT], -1);
  assert_int_equal(r.joint[SMGB_ROLE_HEAD], 4);
  assert_float_equal(smgb_skeleton_leg_length(&t.s), 0.0f, 0.0f);
}

static void test_role_names(void** state) {
  int k;
  (void)state;
  for (k = 0; k < SMGB_ROLE_COUNT; ++k) {
    smgb_role o = smgb_role_counterpart((smgb_role)k);
    assert_int_equal(smgb_role_from_name(smgb_role_name((smgb_role)k)), k);
    assert_int_equal(smgb_role_counterpart(o), k);
  }
  assert_int_equal(smgb_role_counterpart(SMGB_ROLE_LEFT_FOOT),
                   SMGB_ROLE_RIGHT_FOOT);
  assert_int_equal(smgb_role_counterpart(SMGB_ROLE_HEAD), SMGB_ROLE_HEAD);
  assert_int_equal(smgb_role_from_name("tail"), -1);
  assert_int_equal(smgb_role_from_name(NULL), -1);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_conventions), cmocka_unit_test(test_counterparts),
      cmocka_unit_test(test_cmu_layout),  cmocka_unit_test(test_bone_map),
      cmocka_unit_test(test_no_legs),     cmocka_unit_test(test_role_names),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
