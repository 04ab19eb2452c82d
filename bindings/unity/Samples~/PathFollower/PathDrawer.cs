// Path-follower sample: draw a path on the ground with the left mouse
// button and the character follows it while you draw; R / W put a run /
// walk transition and P / N a punch / "none" splice one metre ahead of
// the character. Without input it walks the S-curve set up in Start.
// Uses the legacy Input Manager (Project Settings > Player > Active Input
// Handling: "Input Manager" or "Both").
using System.Collections.Generic;
using Smg.Unity;
using UnityEngine;

namespace Smg.Samples
{
    public sealed class PathDrawer : MonoBehaviour
    {
        public SmgPathCharacter character;
        public LineRenderer line;
        public Camera view;

        [Tooltip("Metres between drawn points.")]
        public float spacing = 0.3f;

        public string runStyle = "run";
        public string walkStyle = "walk";
        public string spliceAction = "punch";

        readonly List<Vector3> points = new List<Vector3>();

        // Before the character's Start: it follows this line from its
        // first frame (a scene may leave Line empty: one is made here).
        void Awake()
        {
            if (line == null)
            {
                line = gameObject.AddComponent<LineRenderer>();
                line.widthMultiplier = 0.05f;
            }
            if (character.pathLine == null)
                character.pathLine = line;
        }

        void Start()
        {
            line.useWorldSpace = true;
            if (line.positionCount == 0)
            {
                Vector3 o = character.transform.position;
                for (int i = 0; i <= 40; ++i)
                {
                    float z = 0.5f * i;
                    points.Add(o + new Vector3(3.0f * Mathf.Sin(z / 3.0f), 0.0f, z));
                }
                Show();
            }
        }

        void Update()
        {
            if (view == null)
                view = Camera.main;
            var ground = new Plane(Vector3.up, new Vector3(0.0f, character.transform.position.y, 0.0f));
            if (Input.GetMouseButton(0))
            {
                Ray ray = view.ScreenPointToRay(Input.mousePosition);
                float t;
                if (ground.Raycast(ray, out t))
                {
                    Vector3 p = ray.GetPoint(t);
                    if (Input.GetMouseButtonDown(0))
                        points.Clear();
                    if (points.Count == 0 || Vector3.Distance(points[points.Count - 1], p) >= spacing)
                    {
                        points.Add(p);
                        Show();
                    }
                }
            }
            if (Input.GetKeyDown(KeyCode.R))
                character.AddTransition(Ahead(), runStyle);
            if (Input.GetKeyDown(KeyCode.W))
                character.AddTransition(Ahead(), walkStyle);
            if (Input.GetKeyDown(KeyCode.P))
                character.AddSplice(Ahead(), spliceAction);
            if (Input.GetKeyDown(KeyCode.N))
                character.AddSplice(Ahead(), "none");
        }

        // One metre ahead along the path, within the path.
        float Ahead()
        {
            return Mathf.Min(character.State.PathDistance + 1.0f, character.Character.PathLength);
        }

        // The character follows the line (SmgPathCharacter.followLineChanges).
        void Show()
        {
            line.positionCount = points.Count;
            for (int i = 0; i < points.Count; ++i)
                line.SetPosition(i, points[i] + new Vector3(0.0f, 0.02f, 0.0f));
        }
    }
}
