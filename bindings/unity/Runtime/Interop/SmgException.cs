// A failed smg_result as an exception: the message is the function's name,
// libsmg's own text for the code (smg_result_string) and, for loads, the
// line libsmg logged saying what is wrong (section, record, field).
using System;

namespace Smg
{
    public sealed class SmgException : Exception
    {
        /// <summary>The smg_result the call returned.</summary>
        public SmgResult Result { get; }

        /// <summary>The C function that failed.</summary>
        public string Function { get; }

        public SmgException(SmgResult result, string function, string detail = null)
            : base(Format(result, function, detail))
        {
            Result = result;
            Function = function;
        }

        /// <summary>smg_result_string's text for a code.</summary>
        public static string ResultString(SmgResult result)
        {
            return SmgUtf8.Decode(SmgNative.smg_result_string(result));
        }

        static string Format(SmgResult result, string function, string detail)
        {
            string text = function + ": " + ResultString(result);
            return string.IsNullOrEmpty(detail) ? text : text + " (" + detail + ")";
        }

        /// <summary>Throws for anything but SmgResult.Ok. The function name
        /// is a literal at every call site, so success allocates nothing.</summary>
        public static void Check(SmgResult result, string function)
        {
            if (result != SmgResult.Ok)
                throw new SmgException(result, function);
        }
    }
}
