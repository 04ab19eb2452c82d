// Blittable mirrors of the public structs of include/smg.h, field for field
// and in the same order (C name snake_case -> C# PascalCase; float[3] ->
// SmgFloat3; pointers and function pointers -> IntPtr). The C# test compares
// every size and offset with the C compiler's, so a drift fails `make test`.
// New C fields go at the end of the C struct: add them at the end here too.
using System;
using System.Runtime.InteropServices;

namespace Smg
{
    /// <summary>Three floats (x, y, z): a C float[3].</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgFloat3
    {
        public float X, Y, Z;

        public SmgFloat3(float x, float y, float z)
        {
            X = x;
            Y = y;
            Z = z;
        }
    }

    /// <summary>smg_allocator: native function pointers. Managed code sets
    /// these through SmgGraphOptions / SmgCharacter.Create rather than by
    /// hand.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgAllocator
    {
        public IntPtr Alloc;
        public IntPtr Free;
        public IntPtr User;
    }

    /// <summary>smg_logger.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgLogger
    {
        public IntPtr Func;
        public IntPtr User;
    }

    /// <summary>smg_graph_desc.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgGraphDesc
    {
        public uint StructSize;
        public SmgGraphFlags Flags;
        public SmgAllocator Allocator;
        public SmgLogger Logger;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgGraphDesc));

        /// <summary>All defaults, StructSize set.</summary>
        public static SmgGraphDesc Create()
        {
            return new SmgGraphDesc { StructSize = Size };
        }
    }

    /// <summary>smg_graph_info.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgGraphInfo
    {
        public uint StructSize;
        public uint FormatVersion;
        public uint JointCount;
        public uint StyleCount;
        public uint ActionCount;
        public uint FrameCount;
        public uint LowerNodeCount;
        public uint LowerEdgeCount;
        public uint UpperNodeCount;
        public uint UpperEdgeCount;
        public uint SpliceCount;
        public uint CharacterCount;
        public float FrameRate;
        public float Reserved0;
        public ulong BlobSize;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgGraphInfo));

        public static SmgGraphInfo Create()
        {
            return new SmgGraphInfo { StructSize = Size };
        }
    }

    /// <summary>smg_joint_info. Name points into the graph (UTF-8, valid
    /// while the graph lives); SmgGraph.GetJoint returns it as a string.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgJointInfo
    {
        public uint StructSize;
        public int Parent;
        public IntPtr Name;
        public SmgFloat3 RestOffset;
        public SmgBodyPart BodyPart;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgJointInfo));

        public static SmgJointInfo Create()
        {
            return new SmgJointInfo { StructSize = Size };
        }
    }

    /// <summary>smg_character_desc: zero fields mean the documented
    /// defaults.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgCharacterDesc
    {
        public uint StructSize;
        public SmgCharacterFlags Flags;
        public uint InitialStyle;
        public uint InitialAction;
        public uint PathCapacity;
        public uint ConstraintCapacity;
        public uint Seed;
        public uint Reserved0;
        public SmgFloat3 Position;
        public float Heading;
        public float Horizon;
        public float ErrorThreshold;
        public SmgAllocator Allocator;
        public float SteerTurnRate;
        public float SteerSlideRatio;
        public float StopSeconds;
        /// <summary>Metres a fast swinging toe clears the floor by; 0 = 0.04 leg lengths.</summary>
        public float SwingClearance;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgCharacterDesc));

        /// <summary>All defaults, StructSize set.</summary>
        public static SmgCharacterDesc Create()
        {
            return new SmgCharacterDesc { StructSize = Size };
        }
    }

    /// <summary>smg_character_state.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgCharacterState
    {
        public uint StructSize;
        public SmgStateFlags Flags;
        public uint Style;
        public uint Action;
        public SmgFloat3 Position;
        public float Heading;
        public float PathDistance;
        public float PathError;
        public double Time;
        public uint LowerNode;
        public uint UpperNode;
        public float SyncRate;
        public float Reserved0;
        public float SteerTurnRate;
        public float SteerSlideSpeed;
        public float PlaybackRate;
        public float Reserved1;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgCharacterState));

        public static SmgCharacterState Create()
        {
            return new SmgCharacterState { StructSize = Size };
        }
    }

    /// <summary>Two floats: a C float[2] (per foot: left, right).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgFloat2
    {
        public float X, Y;

        public SmgFloat2(float x, float y)
        {
            X = x;
            Y = y;
        }
    }

    /// <summary>smg_event: one entry of smg_character_get_events.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgEvent
    {
        public uint StructSize;
        public SmgEventType Type;
        /// <summary>Constraint: the id AddTransition/AddSplice returned (0:
        /// a change no constraint asked for). Footstep: 0 left, 1 right.</summary>
        public uint Id;
        /// <summary>Constraint: its style or action.</summary>
        public uint Value;
        public SmgEventFlags Flags;
        /// <summary>Footstep: the toe where it landed (world); others: the
        /// character's ground position.</summary>
        public SmgFloat3 Position;
        /// <summary>Footstep: the toe's downward speed as it landed, m/s.</summary>
        public float Strength;
        public float ArcLength;
        public uint Reserved0;
        public uint Reserved1;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgEvent));
    }

    /// <summary>smg_root_motion: the ground position's displacement over
    /// the last step.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgRootMotion
    {
        public uint StructSize;
        public uint Flags;
        public SmgFloat3 Translation;
        public float Yaw;
        public SmgFloat3 LocalTranslation;
        public float Reserved0;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgRootMotion));

        public static SmgRootMotion Create()
        {
            return new SmgRootMotion { StructSize = Size };
        }
    }

    /// <summary>smg_ground: ground heights at the probes of
    /// smg_character_get_ground_probes (left foot, right foot, root).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmgGround
    {
        public uint StructSize;
        public uint Flags;
        public SmgFloat2 FootHeight;
        public float RootHeight;
        public float Reserved0;

        public static readonly uint Size = (uint)Marshal.SizeOf(typeof(SmgGround));

        public static SmgGround Create()
        {
            return new SmgGround { StructSize = Size };
        }
    }
}
