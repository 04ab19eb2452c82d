// Every smg_ function libsmg.so exports has a [DllImport] in SmgNative and
// every [DllImport] (SmgNative's and SmgNativeRaw's per-frame subset) names
// an exported function, so a function added to the library fails this test
// until the binding declares it.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;

namespace Smg.Tests
{
    static class ExportTest
    {
        public static void Run(string[] exportedLines)
        {
            var exported = new HashSet<string>(exportedLines.Select(l => l.Trim()).Where(l => l.StartsWith("smg_")));
            var imported = Imports(typeof(SmgNative));
            var raw = Imports(typeof(SmgNativeRaw));
            Check.True(exported.Count >= 30, "the export list holds libsmg's functions (got " + exported.Count + ")");
            var missing = exported.Except(imported).OrderBy(s => s).ToList();
            var extra = imported.Union(raw).Except(exported).OrderBy(s => s).ToList();
            if (missing.Count > 0 || extra.Count > 0)
                throw new Exception("libsmg.so exports without a DllImport in SmgNative: [" + string.Join(", ", missing)
                                    + "]; DllImports libsmg.so does not export: [" + string.Join(", ", extra) + "]");
        }

        static HashSet<string> Imports(Type type)
        {
            var imported = new HashSet<string>();
            foreach (MethodInfo m in type.GetMethods(BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static))
            {
                if ((m.Attributes & MethodAttributes.PinvokeImpl) == 0)
                    continue;
                var import = (DllImportAttribute)m.GetCustomAttributes(typeof(DllImportAttribute), false).Single();
                Check.Equal(SmgNative.Library, import.Value, m.Name + " library");
                Check.Equal(CallingConvention.Cdecl, import.CallingConvention, m.Name + " calling convention");
                imported.Add(import.EntryPoint ?? m.Name);
            }
            return imported;
        }
    }
}
