// Enums and flag sets of include/smg.h. Each member is the C constant with
// its prefix removed and the rest in PascalCase (SMG_STATE_HAS_PATH ->
// SmgStateFlags.HasPath); the C# test checks every C value against these.
using System;

namespace Smg
{
    /// <summary>smg_result: SMG_OK is 0; every other value is an error.</summary>
    public enum SmgResult : int
    {
        Ok = 0,
        ErrorInvalidArgument = 1,
        ErrorOutOfMemory = 2,
        ErrorIo = 3,
        ErrorBlobTruncated = 4,
        ErrorBlobMagic = 5,
        ErrorBlobEndian = 6,
        ErrorBlobVersion = 7,
        ErrorBlobAlignment = 8,
        ErrorBlobChecksum = 9,
        ErrorBlobSection = 10,
        ErrorBlobIndex = 11,
        ErrorBlobValue = 12,
        ErrorUnknownStyle = 13,
        ErrorUnknownAction = 14,
        ErrorOutOfRange = 15,
        ErrorCapacity = 16,
        ErrorBufferTooSmall = 17,
        ErrorInUse = 18,
        ErrorNotFound = 19,
        ErrorParse = 20,
        ErrorUnsupported = 21,
    }

    /// <summary>SMG_GRAPH_* load flags.</summary>
    [Flags]
    public enum SmgGraphFlags : uint
    {
        None = 0,
        SkipChecksum = 1,
    }

    /// <summary>SMG_CHARACTER_* creation flags.</summary>
    [Flags]
    public enum SmgCharacterFlags : uint
    {
        None = 0,
        NoIk = 1,
        NoSteering = 2,
        NoSwingClearance = 4,
    }

    /// <summary>SMG_STATE_* flags of SmgCharacterState.Flags.</summary>
    [Flags]
    public enum SmgStateFlags : uint
    {
        None = 0,
        HasPath = 1,
        PathEndReached = 2,
        LeftContact = 4,
        RightContact = 8,
    }

    /// <summary>SMG_SPACE_*: the space of smg_character_get_model_matrices.</summary>
    public enum SmgSpace : uint
    {
        World = 0,
        Character = 1,
    }

    /// <summary>SMG_BODY_*: which half of the body a joint belongs to.</summary>
    public enum SmgBodyPart : uint
    {
        Root = 0,
        Lower = 1,
        Upper = 2,
    }

    /// <summary>SMG_LOG_*: the level passed to a logger.</summary>
    public enum SmgLogLevel : uint
    {
        Error = 1,
        Warning = 2,
        Info = 3,
    }

    /// <summary>smg_event.type (SMG_EVENT_CONSTRAINT, _FOOTSTEP, _PATH_END).</summary>
    public enum SmgEventType : uint
    {
        Constraint = 1,
        Footstep = 2,
        PathEnd = 3,
    }

    /// <summary>smg_event.flags of a constraint event.</summary>
    [Flags]
    public enum SmgEventFlags : uint
    {
        None = 0,
        Splice = 1,
        Superseded = 2,
        Unchanged = 4,
    }
}
