// Humanoid body bones with the values of Unity's HumanBodyBones (the
// component casts between the two), so the bone mapping can live in this
// engine-free assembly and be tested without Unity. Fingers, eyes and jaw
// are not listed: libsmg's graphs do not animate them as such.
namespace Smg
{
    public enum SmgHumanBone
    {
        None = -1,
        Hips = 0,
        LeftUpperLeg = 1,
        RightUpperLeg = 2,
        LeftLowerLeg = 3,
        RightLowerLeg = 4,
        LeftFoot = 5,
        RightFoot = 6,
        Spine = 7,
        Chest = 8,
        Neck = 9,
        Head = 10,
        LeftShoulder = 11,
        RightShoulder = 12,
        LeftUpperArm = 13,
        RightUpperArm = 14,
        LeftLowerArm = 15,
        RightLowerArm = 16,
        LeftHand = 17,
        RightHand = 18,
        LeftToes = 19,
        RightToes = 20,
        UpperChest = 54,
    }
}
