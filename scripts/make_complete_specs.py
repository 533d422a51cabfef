#!/usr/bin/env python3
"""Writes data/complete/: the benchmark problems of the complete solvers (issue 15) as relpos specs.

- stewart-gough-dietmaier-40.json: Dietmaier's general 6-6 Stewart-Gough platform with 40 real
  poses (P. Dietmaier, "The Stewart-Gough platform of general geometry can have 40 real postures",
  ARK 1998). The geometry is the Maple program in PHCpack's demo system `stewgou40` (Debian package
  phcpack-doc, /usr/share/doc/phcpack/examples/stewgou40): base points a_i, platform points b_i in
  the platform frame (a1, a2, a1 x a2), leg lengths L1 = 1, L2..L6. Its 40 listed real solutions
  (n = platform origin, a1, a2 = first two columns of the rotation) are written beside it as
  stewart-gough-dietmaier-40.literature-poses.json, a check of the transcription.
- octahedral-a.json, octahedral-b.json: paper 001 section V-A. Base p1 p2 p3 equilateral of side
  sqrt(3) (circumradius 1), platform p4 p5 p6 of side sqrt(3)/2 (circumradius 1/2), turned 60 deg
  so that each platform point sits between the two base points it is joined to; legs p1p5, p1p6,
  p2p6, p2p4, p3p4, p3p5; squared lengths a: r15 = r26 = r34 = 4.25, r16 = r24 = r35 = 5.75;
  b: all 4.75.
- four-spheres-12-lines.json: paper 001 section V-B. Centres pairwise sqrt(8) apart (a regular
  tetrahedron, the vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)), radii 1.45; the mobile
  object is one line, at distance 1.45 from each centre (12 real tangent lines).
Usage: scripts/make_complete_specs.py [PHC_STEWGOU40_FILE]
"""
import json, math, os, re, sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, '..', 'data', 'complete')


def spec(name, fixed, mobile, constraints, mobile_pose):
    return {
        'relpos': 1, 'name': name,
        'fixed': {'name': 'base', 'features': fixed},
        'mobile': {'name': 'platform', 'pose': mobile_pose, 'features': mobile},
        'constraints': constraints,
    }


def write(name, doc):
    with open(os.path.join(OUT, name), 'w') as f:
        json.dump(doc, f, indent=2)
        f.write('\n')


def dietmaier():
    a = [(0, 0, 0), (1.107915, 0, 0), (0.549094, 0.756063, 0), (0.735077, -0.223935, 0.525991),
         (0.514188, -0.526063, -0.368418), (0.590473, 0.094733, -0.205018)]
    b = [(0, 0, 0), (0.542805, 0, 0), (0.956919, -0.528915, 0), (0.665885, -0.353482, 1.402538),
         (0.478359, 1.158742, 0.107672), (-0.137087, -0.235121, 0.353913)]
    L = [1.0, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071]
    fixed = {'A%d' % (i + 1): {'point': list(p)} for i, p in enumerate(a)}
    mobile = {'B%d' % (i + 1): {'point': list(p)} for i, p in enumerate(b)}
    cons = [{'type': 'distance', 'fixed': 'A%d' % (i + 1), 'mobile': 'B%d' % (i + 1),
             'value': L[i], 'id': 'leg%d' % (i + 1)} for i in range(6)]
    write('stewart-gough-dietmaier-40.json',
          spec('stewart-gough-dietmaier-40', fixed, mobile, cons, {'position': [0.5, 0, 0]}))


def dietmaier_literature_poses(path):
    text = open(path).read().split('THE SOLUTIONS :')[1]
    poses = []
    for block in re.split(r'^solution \d+ :', text, flags=re.M)[1:]:
        v = {m.group(1): float(m.group(2))
             for m in re.finditer(r'^\s*(\w+) :\s+(\S+)\s+\S+\s*$', block, re.M)}
        n = [v['n1'], v['n2'], v['n3']]
        a1 = [v['a11'], v['a12'], v['a13']]
        a2 = [v['a21'], v['a22'], v['a23']]
        a3 = [a1[1] * a2[2] - a1[2] * a2[1], a1[2] * a2[0] - a1[0] * a2[2],
              a1[0] * a2[1] - a1[1] * a2[0]]
        rows = [[a1[r], a2[r], a3[r], n[r]] for r in range(3)] + [[0, 0, 0, 1]]
        poses.append({'matrix': rows})
    assert len(poses) == 40, len(poses)
    with open(os.path.join(OUT, 'stewart-gough-dietmaier-40.literature-poses.json'), 'w') as f:
        json.dump({'source': 'PHCpack demo system stewgou40 (Dietmaier 1998): its 40 real '
                             'solutions as poses of the platform frame',
                   'poses': poses}, f, indent=1)
        f.write('\n')


def octahedral(config):
    def on_circle(r, deg):
        t = math.radians(deg)
        return [r * math.cos(t), r * math.sin(t), 0.0]
    fixed = {'p1': {'point': on_circle(1, 0)}, 'p2': {'point': on_circle(1, 120)},
             'p3': {'point': on_circle(1, 240)}}
    mobile = {'p4': {'point': on_circle(0.5, 180)}, 'p5': {'point': on_circle(0.5, 300)},
              'p6': {'point': on_circle(0.5, 60)}}
    legs = [('p1', 'p5'), ('p1', 'p6'), ('p2', 'p6'), ('p2', 'p4'), ('p3', 'p4'), ('p3', 'p5')]
    squared = {'a': {('p1', 'p5'): 4.25, ('p2', 'p6'): 4.25, ('p3', 'p4'): 4.25,
                     ('p1', 'p6'): 5.75, ('p2', 'p4'): 5.75, ('p3', 'p5'): 5.75},
               'b': {leg: 4.75 for leg in legs}}[config]
    cons = [{'type': 'distance', 'fixed': f, 'mobile': m, 'value': math.sqrt(squared[(f, m)]),
             'id': f + m} for f, m in legs]
    write('octahedral-%s.json' % config,
          spec('octahedral-' + config, fixed, mobile, cons, {'position': [0, 0, 2]}))


def four_spheres():
    centres = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
    fixed = {'c%d' % (i + 1): {'point': list(c)} for i, c in enumerate(centres)}
    mobile = {'l': {'line': {'point': [0, 0, 0], 'direction': [0, 0, 1]}}}
    cons = [{'type': 'distance', 'fixed': 'c%d' % (i + 1), 'mobile': 'l', 'value': 1.45,
             'id': 'sphere%d' % (i + 1)} for i in range(4)]
    write('four-spheres-12-lines.json', spec('four-spheres-12-lines', fixed, mobile, cons, {}))


if __name__ == '__main__':
    os.makedirs(OUT, exist_ok=True)
    dietmaier()
    dietmaier_literature_poses(sys.argv[1] if len(sys.argv) > 1 else
                               '/usr/share/doc/phcpack/examples/stewgou40')
    octahedral('a')
    octahedral('b')
    four_spheres()
