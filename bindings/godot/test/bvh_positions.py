#!/usr/bin/env python3
"""bvh_positions.py IN.bvh TIMES.csv OUT.csv

World joint positions of every frame of a BVH written by smg-synth (any
channel order; rotation channels compose in the order listed, local to the
parent), one line per frame: "time,x0,y0,z0,x1,..." in joint order, with the
times taken from smg-synth's --csv file. The Godot rig test compares the
bones it drives against these.
"""
import math
import sys


def axis_rot(axis, deg):
    a = math.radians(deg)
    c, s = math.cos(a), math.sin(a)
    if axis == "X":
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == "Y":
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def main():
    bvh, times_csv, out = sys.argv[1:4]
    tokens = open(bvh).read().split()
    joints = []  # (parent, offset, channels)
    stack, i = [], 0
    while tokens[i] != "MOTION":
        t = tokens[i]
        if t in ("ROOT", "JOINT"):
            joints.append([stack[-1] if stack else -1, None, []])
            i += 2
        elif t == "End":  # End Site: skip its block
            i = tokens.index("}", i) + 1
        elif t == "{":
            stack.append(len(joints) - 1)
            i += 1
        elif t == "}":
            stack.pop()
            i += 1
        elif t == "OFFSET":
            joints[-1][1] = [float(x) for x in tokens[i + 1:i + 4]]
            i += 4
        elif t == "CHANNELS":
            n = int(tokens[i + 1])
            joints[-1][2] = tokens[i + 2:i + 2 + n]
            i += 2 + n
        else:
            i += 1
    frames = int(tokens[i + 2])
    values = [float(x) for x in tokens[i + 6:]]
    times = [line.split(",")[1] for line in open(times_csv).read().split("\n")[1:] if line]
    if len(times) != frames:
        sys.exit("bvh_positions.py: %d frames but %d times" % (frames, len(times)))
    per = sum(len(j[2]) for j in joints)
    with open(out, "w") as f:
        for fr in range(frames):
            v = values[fr * per:(fr + 1) * per]
            k = 0
            world = []
            for parent, offset, chans in joints:
                pos = list(offset)
                rot = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
                for c in chans:
                    if c.endswith("position"):
                        pos["XYZ".index(c[0])] = v[k]
                    else:
                        rot = mul(rot, axis_rot(c[0], v[k]))
                    k += 1
                if parent < 0:
                    world.append((pos, rot))
                else:
                    pp, pr = world[parent]
                    o = apply(pr, pos)
                    world.append(([pp[0] + o[0], pp[1] + o[1], pp[2] + o[2]], mul(pr, rot)))
            f.write(times[fr] + "," + ",".join("%.6f" % c for p, _ in world for c in p) + "\n")


main()
