// Struct layouts and constants of the C# mirrors vs the C compiler's view
// of smg.h (lines from the generated layout program, see gen_c_layout.py).
// Mirrors are found by name: smg_graph_desc -> Smg.SmgGraphDesc,
// struct_size -> StructSize, SMG_STATE_HAS_PATH -> SmgStateFlags.HasPath.
// A C field or constant without a mirror, a C# field C does not have, or
// any size, offset or value difference fails with its name.
using System;
using System.Collections.Generic;
using System.Reflection;
using System.Runtime.InteropServices;

namespace Smg.Tests
{
    static class LayoutTest
    {
        // constant prefix -> the C# type holding its members (longest first);
        // a prefix may have several homes (event types and event flags
        // share SMG_EVENT_): the constant must be in one of them
        static readonly KeyValuePair<string, Type>[] ConstantHomes =
        {
            new KeyValuePair<string, Type>("SMG_EVENT_", typeof(SmgEventType)),
            new KeyValuePair<string, Type>("SMG_EVENT_", typeof(SmgEventFlags)),
            new KeyValuePair<string, Type>("SMG_CHARACTER_", typeof(SmgCharacterFlags)),
            new KeyValuePair<string, Type>("SMG_GRAPH_", typeof(SmgGraphFlags)),
            new KeyValuePair<string, Type>("SMG_STATE_", typeof(SmgStateFlags)),
            new KeyValuePair<string, Type>("SMG_SPACE_", typeof(SmgSpace)),
            new KeyValuePair<string, Type>("SMG_BODY_", typeof(SmgBodyPart)),
            new KeyValuePair<string, Type>("SMG_LOG_", typeof(SmgLogLevel)),
            new KeyValuePair<string, Type>("SMG_ERROR_", typeof(SmgResult)),
            new KeyValuePair<string, Type>("SMG_OK", typeof(SmgResult)),
            new KeyValuePair<string, Type>("SMG_", typeof(SmgNative)),
        };

        public static string Pascal(string snake)
        {
            var parts = snake.ToLowerInvariant().Split(new[] { '_' }, StringSplitOptions.RemoveEmptyEntries);
            for (int i = 0; i < parts.Length; ++i)
                parts[i] = char.ToUpperInvariant(parts[i][0]) + parts[i].Substring(1);
            return string.Concat(parts);
        }

        static int FieldSize(Type t)
        {
            if (t.IsEnum)
                t = Enum.GetUnderlyingType(t);
            if (t == typeof(IntPtr) || t == typeof(UIntPtr))
                return IntPtr.Size;
            return Marshal.SizeOf(t);
        }

        public static void Run(string[] lines)
        {
            var problems = new List<string>();
            var cFields = new Dictionary<Type, HashSet<string>>();
            var resultNames = new HashSet<string>();
            Assembly binding = typeof(SmgNative).Assembly;
            int structs = 0, fields = 0, constants = 0;
            foreach (string line in lines)
            {
                string[] w = line.Split(' ');
                if (w[0] == "struct")
                {
                    ++structs;
                    Type t = binding.GetType("Smg." + Pascal(w[1]));
                    if (t == null)
                    {
                        problems.Add("C struct " + w[1] + " has no mirror Smg." + Pascal(w[1]));
                        continue;
                    }
                    cFields[t] = new HashSet<string>();
                    if (Marshal.SizeOf(t) != int.Parse(w[2]))
                        problems.Add("sizeof(" + w[1] + ") is " + w[2] + " in C, " + Marshal.SizeOf(t) + " in C#");
                }
                else if (w[0] == "field")
                {
                    ++fields;
                    Type t = binding.GetType("Smg." + Pascal(w[1]));
                    if (t == null)
                        continue; // reported with its struct line
                    string name = Pascal(w[2]);
                    cFields[t].Add(name);
                    FieldInfo f = t.GetField(name, BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
                    if (f == null)
                    {
                        problems.Add("C field " + w[1] + "." + w[2] + " has no mirror " + t.Name + "." + name);
                        continue;
                    }
                    int offset = (int)Marshal.OffsetOf(t, name);
                    if (offset != int.Parse(w[3]) || FieldSize(f.FieldType) != int.Parse(w[4]))
                        problems.Add(w[1] + "." + w[2] + " is at " + w[3] + " size " + w[4] + " in C, at " + offset
                                     + " size " + FieldSize(f.FieldType) + " in C#");
                }
                else if (w[0] == "const")
                {
                    ++constants;
                    if (w[1].StartsWith("SMG_OK") || w[1].StartsWith("SMG_ERROR_"))
                        resultNames.Add(Pascal(w[1].Substring(4)));
                    CheckConstant(w[1], long.Parse(w[2]), problems);
                }
            }
            foreach (var entry in cFields)
                foreach (FieldInfo f in entry.Key.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
                    if (!entry.Value.Contains(f.Name))
                        problems.Add("C# field " + entry.Key.Name + "." + f.Name + " is not in the C struct");
            foreach (string name in Enum.GetNames(typeof(SmgResult)))
                if (!resultNames.Contains(name))
                    problems.Add("SmgResult." + name + " is not an smg_result value");
            Check.True(structs >= 7 && fields >= 50 && constants >= 40,
                       "the layout file lists smg.h's structs, fields and constants (got " + structs + ", " + fields + ", " + constants + ")");
            if (problems.Count > 0)
                throw new Exception("binding out of step with smg.h:\n  " + string.Join("\n  ", problems));
        }

        static void CheckConstant(string cName, long value, List<string> problems)
        {
            string prefix = null;
            var homes = new List<string>();
            foreach (var home in ConstantHomes)
            {
                if (!cName.StartsWith(home.Key) || (prefix != null && home.Key != prefix))
                    continue;
                prefix = home.Key;
                Type t = home.Value;
                homes.Add(t.Name);
                string rest = t == typeof(SmgResult) ? cName.Substring(4) : cName.Substring(home.Key.Length);
                string name = Pascal(rest);
                long? mirrored = null;
                if (t.IsEnum && Enum.IsDefined(t, name))
                    mirrored = Convert.ToInt64(Enum.Parse(t, name));
                else if (!t.IsEnum)
                {
                    FieldInfo f = t.GetField(name, BindingFlags.Public | BindingFlags.Static);
                    if (f != null && f.IsLiteral)
                        mirrored = Convert.ToInt64(f.GetRawConstantValue());
                }
                if (mirrored == null)
                    continue;
                if (mirrored.Value != value)
                    problems.Add(cName + " is " + value + " in C, " + mirrored.Value + " in " + t.Name + "." + name);
                return;
            }
            if (prefix == null)
                problems.Add("C constant " + cName + " has no home in the binding");
            else
                problems.Add("C constant " + cName + " has no mirror in " + string.Join(" or ", homes));
        }
    }
}
