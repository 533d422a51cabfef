#!/usr/bin/env python3
"""Writes data/start_systems/specs/: small specs whose families get a stored start system
(complete/tools/make_start_systems.cpp, listed in data/start_systems/specs.list), for signatures
robotics tasks produce beside the benchmark problems of data/complete. Only the signature
matters (which equations on which shared features): the geometry is generic (seeded random),
and the values are those of one true pose, so each spec is also a consistent problem.

- six-point-planes: six contacts of mobile points on six generic fixed planes.
- three-legs-three-planes: three distance legs and three point-plane contacts.
- five-legs-one-plane: a five-leg platform with one point on a plane.
- two-angles-four-legs: two line-line angles (a tool axis) and four distance legs.
Usage: scripts/make_start_system_specs.py
"""
import json, math, os, random

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, '..', 'data', 'start_systems', 'specs')
rng = random.Random(20261202)


def vec():
    return [round(rng.uniform(-1, 1), 6) for _ in range(3)]


def unit():
    v = [rng.gauss(0, 1) for _ in range(3)]
    n = math.sqrt(sum(x * x for x in v))
    return [round(x / n, 6) for x in v]


def rotation():
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    w, x, y, z = (c / n for c in q)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]], [w, x, y, z]


R, QUAT = rotation()
T = [0.3, -0.2, 1.5]


def world(b):
    return [sum(R[i][j] * b[j] for j in range(3)) + T[i] for i in range(3)]


def turn(m):
    return [sum(R[i][j] * m[j] for j in range(3)) for i in range(3)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


class Spec:
    def __init__(self, name):
        self.name, self.fixed, self.mobile, self.constraints = name, {}, {}, []

    def leg(self, a, b):
        fa, mb = self.fixed.setdefault(a[0], {'point': a[1]}), self.mobile.setdefault(b[0], {'point': b[1]})
        d = math.dist(world(b[1]), a[1])
        self.constraints.append({'type': 'distance', 'fixed': a[0], 'mobile': b[0], 'value': d,
                                 'id': a[0] + b[0]})

    def contact(self, plane, b):
        n, a = plane[1], plane[2]
        self.fixed[plane[0]] = {'plane': {'point': a, 'normal': n}}
        self.mobile.setdefault(b[0], {'point': b[1]})
        d = dot(sub(world(b[1]), a), n) / math.sqrt(dot(n, n))
        self.constraints.append({'type': 'distance', 'fixed': plane[0], 'mobile': b[0], 'value': d,
                                 'id': plane[0] + b[0]})

    def angle(self, u, m):
        self.fixed[u[0]] = {'line': {'point': [0, 0, 0], 'direction': u[1]}}
        self.mobile[m[0]] = {'line': {'point': [0, 0, 0], 'direction': m[1]}}
        c = dot(u[1], turn(m[1])) / math.sqrt(dot(u[1], u[1]) * dot(m[1], m[1]))
        self.constraints.append({'type': 'angle', 'fixed': u[0], 'mobile': m[0],
                                 'value': math.acos(max(-1, min(1, c))), 'id': u[0] + m[0]})

    def write(self):
        w, x, y, z = QUAT
        s = {'relpos': 1, 'name': self.name, 'fixed': {'name': 'base', 'features': self.fixed},
             'mobile': {'name': 'platform', 'pose': {'position': T, 'orientation': [x, y, z, w]},
                        'features': self.mobile},
             'constraints': self.constraints}
        with open(os.path.join(OUT, self.name + '.json'), 'w') as f:
            json.dump(s, f, indent=2)
            f.write('\n')


def pts(prefix, k):
    return [(prefix + str(i + 1), vec()) for i in range(k)]


def planes(k):
    return [('n' + str(i + 1), unit(), vec()) for i in range(k)]


os.makedirs(OUT, exist_ok=True)
s = Spec('six-point-planes')
for pl, b in zip(planes(6), pts('b', 6)):
    s.contact(pl, b)
s.write()


def legs_and_contacts(name, legs):
    """legs distance legs, then 6 - legs point-plane contacts, on six mobile points."""
    s = Spec(name)
    bs = pts('b', 6)
    for a, b in zip(pts('a', legs), bs[:legs]):
        s.leg(a, b)
    for pl, b in zip(planes(6 - legs), bs[legs:]):
        s.contact(pl, b)
    s.write()


legs_and_contacts('three-legs-three-planes', 3)
legs_and_contacts('five-legs-one-plane', 5)
s = Spec('two-angles-four-legs')
s.angle(('u1', unit()), ('m1', unit()))
s.angle(('u2', unit()), ('m2', unit()))
for a, b in zip(pts('a', 4), pts('b', 4)):
    s.leg(a, b)
s.write()
