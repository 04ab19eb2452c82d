// UTF-8 strings across the ABI without relying on the marshaller (whose
// LPStr is the ANSI code page on Windows): names in, names out.
using System;
using System.Text;

namespace Smg
{
    static unsafe class SmgUtf8
    {
        /// <summary>NUL-terminated UTF-8 bytes of s.</summary>
        public static byte[] Encode(string s)
        {
            if (s == null)
                throw new ArgumentNullException(nameof(s));
            var bytes = new byte[Encoding.UTF8.GetByteCount(s) + 1];
            Encoding.UTF8.GetBytes(s, 0, s.Length, bytes, 0);
            return bytes;
        }

        /// <summary>The string at a NUL-terminated UTF-8 pointer (null for
        /// IntPtr.Zero).</summary>
        public static string Decode(IntPtr p)
        {
            if (p == IntPtr.Zero)
                return null;
            byte* b = (byte*)p;
            int n = 0;
            while (b[n] != 0)
                ++n;
            return Encoding.UTF8.GetString(b, n);
        }
    }
}
