# Writes the small hand-made ASCII gmsh meshes of tests/data used by
# tests/unit/fe/geometry_test.cc (run it inside tests/data).
#   python3 make_test_meshes.py
# Writes small ASCII gmsh meshes for the geometry tests.
# 2D: the rectangle [0,2] x [0,1], vertices on a 3 x 2 grid, 4 triangles.
P2 = [(0,0),(1,0),(2,0),(0,1),(1,1),(2,1)]          # node tags 1..6
T2 = [(1,2,5),(1,5,4),(2,3,6),(2,6,5)]
L2 = {1: [(1,2),(2,3)], 2: [(3,6)], 3: [(6,5),(5,4)], 4: [(4,1)]}
N2 = {1:'bottom', 2:'right', 3:'top', 4:'left'}

def v22(fn, names=True, skip=(), points=False):
    # points: a physical group of points (dimension 0) on a corner and on a
    # seventh node that no cell uses (readers drop it).
    nodes = P2 + [(3, 3)] if points else P2
    out = ['$MeshFormat','2.2 0 8','$EndMeshFormat']
    if names:
        out += ['$PhysicalNames', str(len(N2)+1+points)]
        out += ['0 5 "marks"'] if points else []
        out += ['1 %d "%s"' % (t, n) for t, n in N2.items()]
        out += ['2 10 "body"', '$EndPhysicalNames']
    out += ['$Nodes', str(len(nodes))]
    out += ['%d %g %g 0' % (i+1, x, y) for i, (x, y) in enumerate(nodes)]
    out += ['$EndNodes']
    el = ['15 2 5 5 1', '15 2 5 6 7'] if points else []
    for t, lines in L2.items():
        if t in skip: continue
        for a, b in lines: el.append('1 2 %d %d %d %d' % (t, t, a, b))
    for a, b, c in T2: el.append('2 2 10 1 %d %d %d' % (a, b, c))
    out += ['$Elements', str(len(el))]
    out += ['%d %s' % (i+1, e) for i, e in enumerate(el)]
    out += ['$EndElements']
    open(fn, 'w').write('\n'.join(out) + '\n')

def v41(fn):
    out = ['$MeshFormat','4.1 0 8','$EndMeshFormat']
    out += ['$PhysicalNames', str(len(N2)+1)]
    out += ['1 %d "%s"' % (t, n) for t, n in N2.items()]
    out += ['2 10 "body"', '$EndPhysicalNames']
    # Entities: 4 corner points, 4 curves (tag = physical tag), 1 surface.
    corners = [1, 3, 6, 4]
    out += ['$Entities', '4 4 1 0']
    for k, n in enumerate(corners):
        x, y = P2[n-1]
        out.append('%d %g %g 0 0' % (k+1, x, y))
    bounds = {1: (1,2), 2: (2,3), 3: (3,4), 4: (4,1)}
    for t, lines in L2.items():
        xs = [P2[v-1][0] for l in lines for v in l]; ys = [P2[v-1][1] for l in lines for v in l]
        a, b = bounds[t]
        out.append('%d %g %g 0 %g %g 0 1 %d 2 %d -%d' % (t, min(xs), min(ys), max(xs), max(ys), t, a, b))
    out.append('1 0 0 0 2 1 0 1 10 4 1 2 3 4')
    out += ['$EndEntities']
    out += ['$Nodes', '1 %d 1 %d' % (len(P2), len(P2)), '2 1 0 %d' % len(P2)]
    out += [str(i+1) for i in range(len(P2))]
    out += ['%g %g 0' % p for p in P2]
    out += ['$EndNodes']
    nel = sum(len(l) for l in L2.values()) + len(T2)
    out += ['$Elements', '%d %d 1 %d' % (len(L2)+1, nel, nel)]
    tag = 1
    for t, lines in L2.items():
        out.append('1 %d 1 %d' % (t, len(lines)))
        for a, b in lines:
            out.append('%d %d %d' % (tag, a, b)); tag += 1
    out.append('2 1 2 %d' % len(T2))
    for a, b, c in T2:
        out.append('%d %d %d %d' % (tag, a, b, c)); tag += 1
    out += ['$EndElements']
    open(fn, 'w').write('\n'.join(out) + '\n')

# 3D: the unit cube split into the 6 tetrahedra around its diagonal 0-7.
P3 = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]   # index = x + 2y + 4z
paths = [(1,2),(2,1),(1,4),(4,1),(2,4),(4,2)]
T3 = []
for a, b in paths:
    T3.append((0, a, a+b, 7))
F3 = {1: ('xmin', 0, 0), 2: ('xmax', 0, 1), 3: ('ymin', 1, 0), 4: ('ymax', 1, 1), 5: ('zmin', 2, 0), 6: ('zmax', 2, 1)}
def v22_3d(fn):
    out = ['$MeshFormat','2.2 0 8','$EndMeshFormat','$PhysicalNames', str(len(F3)+1)]
    out += ['2 %d "%s"' % (t, n[0]) for t, n in F3.items()] + ['3 20 "cube"', '$EndPhysicalNames']
    out += ['$Nodes', str(len(P3))] + ['%d %g %g %g' % ((i+1,) + p) for i, p in enumerate(P3)] + ['$EndNodes']
    el = []
    for t, (name, d, side) in F3.items():
        for tet in T3:
            face = [v for v in tet if P3[v][d] == side]
            if len(face) == 3:
                el.append('2 2 %d %d %d %d %d' % (t, t, face[0]+1, face[1]+1, face[2]+1))
    for tet in T3:
        el.append('4 2 20 1 %d %d %d %d' % tuple(v+1 for v in tet))
    out += ['$Elements', str(len(el))] + ['%d %s' % (i+1, e) for i, e in enumerate(el)] + ['$EndElements']
    open(fn, 'w').write('\n'.join(out) + '\n')

v22('rectangle_2x1_v22.msh')
v41('rectangle_2x1_v41.msh')
v22('rectangle_2x1_no_names.msh', names=False)
v22('rectangle_2x1_open_side.msh', skip=(2,))
v22('rectangle_2x1_points.msh', points=True)
v22_3d('cube_v22.msh')
