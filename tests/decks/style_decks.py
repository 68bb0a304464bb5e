"""One short deck per LIGGGHTS style, for test_style_matrix.py: the base deck (18 rocks of 20
triangles settling onto a mesh floor, periodic in x and y, LIGGGHTS's hooke material, pair
tri/gran, fix tri/wall, gravity, tri/nve), then the style's lines, then `run 20` (unless the
lines run themselves). The lines use the style as a deck would and make it do its work: a
compute is read by thermo or a dump, a region by a group, a dump writes frames. IDs start
with s; files the decks read are written by write_files()."""
import os

BASE = """units           si
atom_style      {atom_style}
atom_modify     map array sort 0 0.0
boundary        p p f
newton          off
communicate     single vel yes
region          box block -0.012 0.012 -0.012 0.012 0 0.04 units box
create_box      2 box
neighbor        0.001 bin
neigh_modify    delay 0
timestep        1e-5
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m5 all property/global characteristicVelocity scalar 1.0
lattice         sc 0.0033
region          fill block -0.006 0.006 -0.006 0.006 0.0018 0.008 units box
create_atoms    1 region fill
fix shapes all tri/particles shape r random ntri 20 size 0.004 seed 1 density 2500
pair_style      {pair_style}
pair_coeff      * *
fix cad all mesh/surface file plane.stl type 1
fix walls all tri/wall model hooke mesh cad
fix g all gravity 9.81 vector 0 0 -1
fix integr all tri/nve
thermo 10
"""
PAIR = "tri/gran model hooke"


def plane_stl(z, half):
    """Two triangles: the square |x|, |y| <= half at height z, facing up."""
    corners = [(-half, -half), (half, -half), (half, half), (-half, -half), (half, half),
               (-half, half)]
    facets = ""
    for k in (0, 3):
        facets += " facet normal 0 0 1\n  outer loop\n" + "".join(
            f"   vertex {x:g} {y:g} {z:g}\n" for x, y in corners[k:k + 3]) + \
            "  endloop\n endfacet\n"
    return f"solid p\n{facets}endsolid p\n"


def tet_vtk():
    """The cube [-4 mm, 4 mm]^2 x [0, 8 mm] as five tetrahedra, for region mesh/tet."""
    h = 0.004
    points = [(x, y, z) for z in (0, 2 * h) for y in (-h, h) for x in (-h, h)]
    tets = [(0, 1, 2, 4), (1, 3, 2, 7), (1, 4, 5, 7), (2, 4, 6, 7), (1, 2, 4, 7)]
    lines = ["# vtk DataFile Version 2.0", "cube of five tetrahedra", "ASCII",
             "DATASET UNSTRUCTURED_GRID", f"POINTS {len(points)} double"]
    lines += [f"{x:g} {y:g} {z:g}" for x, y, z in points]
    lines += [f"CELLS {len(tets)} {5 * len(tets)}"] + ["4 " + " ".join(map(str, t)) for t in tets]
    lines += [f"CELL_TYPES {len(tets)}"] + ["10"] * len(tets)
    return "\n".join(lines) + "\n"


ADD_DATA = """LIGGGHTS data file: two spheres to add

2 atoms
2 atom types

-0.012 0.012 xlo xhi
-0.012 0.012 ylo yhi
0 0.04 zlo zhi

Atoms

101 1 0.002 2500 0.0 0.0 0.016
102 2 0.002 2500 0.004 0.004 0.022
"""

FILES = {"plane.stl": plane_stl(0, 0.012), "flow.stl": plane_stl(0.0065, 0.011),
         "lid.stl": plane_stl(0.02, 0.011), "face.stl": plane_stl(0.03, 0.008),
         "tet.vtk": tet_vtk(), "add.data": ADD_DATA}


def write_files(folder):
    for name, text in FILES.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)


def resumed_base(restart, atom_style="sphere", pair_style=PAIR):
    """The base deck reading the restart file `restart` where it would create its box and
    atoms."""
    setup = ("region", "create_box", "lattice", "create_atoms")
    lines = BASE.format(atom_style=atom_style, pair_style=pair_style).splitlines()
    return "".join(f"read_restart {restart}\n" if l.startswith("region          box") else
                   "" if l.startswith(setup) else l + "\n" for l in lines)


def deck_text(key):
    """The deck of style `key` ("kind style"). A snippet is the lines after the base deck, or a
    dict of them ("lines") and of the base's atom_style or pair_style it replaces."""
    snippet = SNIPPETS[key]
    if isinstance(snippet, str):
        snippet = {"lines": snippet}
    base = BASE.format(atom_style=snippet.get("atom_style", "sphere"),
                       pair_style=snippet.get("pair_style", PAIR))
    lines = snippet.get("lines", "")
    runs = any(l.split()[:1] == ["run"] for l in lines.splitlines())
    return base + lines + ("\n" if runs else "\nrun 20\n")


DUMP = "dump sd all custom 10 s.dump id x y z vx vy vz fx fy fz omegax omegay omegaz tqx tqy tqz f_shapes[6] f_shapes[7] f_shapes[8]"
TEMPL = ("fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
         "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
         "region sins block -0.008 0.008 -0.008 0.008 0.015 0.035 units box")
CFD = "fix s0 all couple/cfd couple_every 1 mpi\nfix s1 all property/global thermalConductivity peratomtype 1 1\nfix s2 all property/global thermalCapacity peratomtype 1000 1000"
CHK = "dump schk all custom 10 chk.dump id type x y z radius mass vx vz omegax omegaz f_shapes[1] f_shapes[2] f_shapes[6]\ndump_modify schk sort id"
TH = "thermo_style custom step atoms ke "
# Keys "kind style" as tri-style-matrix names them; "kind style:variant" is one more deck
# of the same style.
SNIPPETS = {
 "fix adapt": "variable sd equal 0.004\nfix s all adapt 1 atom diameter v_sd",
 "fix addforce": "fix s all addforce 0 0 1e-4\nthermo_style custom step f_s[1] f_s[2] f_s[3]\n" + DUMP,
 "fix ave/atom": "fix s all ave/atom 1 10 10 vx vz fz\ndump s all custom 10 s.dump id f_s[1] f_s[2] f_s[3]",
 "fix ave/correlate": "compute s1 all ke\nfix s all ave/correlate 1 5 10 c_s1 file s.cor\nthermo_style custom step c_s1",
 "fix ave/euler": "fix s all ave/euler nevery 5 cell_size_relative 2 parallel no\ndump s all euler/vtk 10 s_*.vtk",
 "fix ave/euler/stress": "fix s all ave/euler/stress nevery 5 cell_size_relative 2 parallel no",
 "fix ave/histo": "fix s all ave/histo 1 10 10 -0.01 0.01 10 vx vz mode vector file s.histo\nthermo_style custom step f_s[1] f_s[2]",
 "fix ave/spatial": "fix s all ave/spatial 1 10 10 z lower 0.002 vz density/mass units box file s.prof",
 "fix ave/time": "compute s1 all ke\nfix s all ave/time 1 10 10 c_s1 file s.time\nthermo_style custom step f_s",
 "fix aveforce": "fix s all aveforce NULL NULL -1e-4\nthermo_style custom step f_s[1] f_s[2] f_s[3]\n" + DUMP,
 "fix box/relax": "fix s all box/relax x 0.0 y 0.0 vmax 0.001\ncompute thermo_pe all pe\nthermo_style custom step lx ly\nminimize 0 0 10 100",
 "fix buoyancy": "fix s all buoyancy level 0.005 dim z density 1000\n" + DUMP,
 "fix couple/cfd": CFD,
 "fix couple/cfd/convection": CFD + "\nfix s all couple/cfd/convection T0 300",
 "fix couple/cfd/radiation": CFD + "\nfix s all couple/cfd/radiation T0 300",
 "fix couple/cfd/convectiveImpl": CFD + "\nfix s all couple/cfd/convectiveImpl integrateHeatEqn true T0 300",
 "fix couple/cfd/speciesConvection": CFD + "\nfix s all couple/cfd/speciesConvection speciesName O2 species0 0.1",
 "fix couple/cfd/force": CFD + "\nfix s all couple/cfd/force",
 "fix couple/cfd/dragforce": CFD + "\nfix s all couple/cfd/dragforce",
 "fix couple/cfd/force/implicit": CFD + "\nfix s all couple/cfd/force/implicit",
 "fix check/timestep/gran": "fix s all check/timestep/gran 10 0.1 0.1\nthermo_style custom step f_s[1] f_s[2]",
 "fix check/timestep/sph": "fix s all check/timestep/sph 10 0.1",
 "fix contacthistory": "fix s all contacthistory 1 shearx 0",
 "fix contacthistory/mesh": "fix s all contacthistory/mesh 3 cad",
 "fix contactproperty/atom": "fix s all contactproperty/atom sc 1 fx 0 reset yes",
 "fix contactproperty/atom/wall": "fix s all contactproperty/atom/wall sc 1 fx 0 mesh cad",
 "fix continuum/weighted": "fix s all continuum/weighted kernel_radius 0.006 kernel_type Wendland compute stress\ndump s all custom 10 s.dump id f_stressTensor_[1] f_stressTensor_[5] f_stressTensor_[9]",
 "fix deform": "fix s all deform 1 x final -0.013 0.013 units box\nthermo_style custom step lx ly",
 "fix deform/check": "run 0\nfix s all deform/check 1 x final -0.013 0.013 units box\nthermo_style custom step lx ly\nrun 20",
 "fix diam/max": TEMPL + "\nfix s all diam/max\nthermo_style custom step f_s",
 "fix drag": "fix s all drag 0 0 0.01 1e-4 0.001\nthermo_style custom step f_s[1] f_s[2] f_s[3]\n" + DUMP,
 "fix dt/reset": "fix s all dt/reset 1 1e-7 2e-5 1e-6 units box\nthermo_style custom step dt f_s",
 "fix efield": "fix s all efield 0.0 0.0 1.0",
 "fix enforce2d": "fix s all enforce2d",
 "fix external": "fix s all external pf/callback 1 1",
 "fix fiber/spring/simple": "fix s all fiber/spring/simple tether 1.0 0 0 0.003 0.0",
 "fix freeze": "group s1 id 1 2 3\nset group s1 omegaz 10\nfix s s1 freeze\nthermo_style custom step f_s[1] f_s[2] f_s[3]\n" + DUMP,
 "fix gravity": "fix s all gravity 1.0 vector 1 0 0\n" + DUMP,
 "fix heat/gran/conduction": "fix s1 all property/global thermalConductivity peratomtype 1 1\nfix s2 all property/global thermalCapacity peratomtype 1000 1000\nfix s all heat/gran/conduction initial_temperature 300",
 "fix heat/gran": "fix s1 all property/global thermalConductivity peratomtype 1 1\nfix s2 all property/global thermalCapacity peratomtype 1000 1000\nfix s all heat/gran initial_temperature 300",
 "fix insert/pack": TEMPL + "\nfix s all insert/pack seed 67867967 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 5 region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix insert/rate/region": TEMPL + "\nfix s all insert/rate/region seed 67867967 distributiontemplate pdd nparticles 5 particlerate 100000 insert_every 10 overlapcheck yes region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix insert/stream": TEMPL + "\nfix sface all mesh/surface file face.stl type 1\nfix s all insert/stream seed 67867967 distributiontemplate pdd nparticles 4 massrate 1 overlapcheck yes vel constant 0 0 -1 insertion_face sface extrude_length 0.01\nthermo_style custom step atoms",
 "fix couple/lb/onetoone": "fix s all couple/lb/onetoone",
 "fix lineforce": "fix s all lineforce 0 0 1\n" + DUMP,
 "fix massflow/mesh": "velocity all set 0 0 -1\nfix sm all mesh/surface file flow.stl type 1\nfix s all massflow/mesh mesh sm vec_side 0 0 -1 count once file s.flow\nthermo_style custom step f_s[1] f_s[2]",
 "fix massflow/mesh/sieve": "velocity all set 0 0 -1\nfix sm all mesh/surface file flow.stl type 1\nfix s all massflow/mesh/sieve mesh sm point_at_outlet 0 0 -1000 count once delete_atoms no sieveSize 2e-3 sieveSpacing 2.5e-3 sieveStiffness 1e3 sieveDamping 1\nthermo_style custom step f_s[1] f_s[2]",
 "fix mesh/surface": "fix s all mesh/surface file lid.stl type 1\nfix sw all tri/wall model hooke mesh s",
 "fix mesh/surface/planar": "fix s all mesh/surface/planar file lid.stl type 1\nfix sw all tri/wall model hooke mesh s",
 "fix momentum": "set atom 1 vx 0.1\nfix s all momentum 1 linear 1 1 1 angular\n" + DUMP,
 "fix move": "group s1 id 1\nfix s s1 move linear 0 0 -0.1",
 "fix move/mesh": "fix s all move/mesh mesh cad wiggle amplitude 0 0 0.0005 period 0.001\n" + DUMP,
 "fix move/mesh/gran": "fix s all move/mesh/gran mesh cad wiggle amplitude 0 0 0.0005 period 0.001\n" + DUMP,
 "fix move/mesh/file": "fix s all move/mesh/file mesh cad wiggle amplitude 0 0 0.0005 period 0.001\n" + DUMP,
 "fix multicontact/halfspace": "fix s all multicontact/halfspace geometric_prefactor 1.8",
 "fix multisphere": "fix s all multisphere",
 "fix multisphere/nointegration": "fix s all multisphere/nointegration",
 "fix concave": "fix s all concave",
 "fix multisphere/break": "fix s all multisphere/break allow_group_and_set yes trigger_threshold 1 trigger_timeStep 0 trigger_name v_sx\nvariable sx atom x",
 "fix neighlist/mesh": "",  # the base deck's mesh makes one for fix tri/wall
 "fix nve": "fix s all nve",
 "fix nve/asphere": "fix s all nve/asphere",
 "fix nve/asphere/noforce": "fix s all nve/asphere/noforce",
 "fix nve/limit": "fix s all nve/limit absolute 0.0001",
 "fix nve/line": "fix s all nve/line",
 "fix nve/noforce": "fix s all nve/noforce",
 "fix nve/sph": "fix s all nve/sph",
 "fix nve/sph/stationary": "fix s all nve/sph/stationary",
 "fix nve/sphere": "fix s all nve/sphere",
 "fix particledistribution/discrete": TEMPL + "\nfix s all insert/pack seed 67867967 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 5 region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix particledistribution/discrete/numberbased": TEMPL.replace("particledistribution/discrete ", "particledistribution/discrete/numberbased ") + "\nfix s all insert/pack seed 67867967 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 5 region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix particledistribution/discrete/massbased": TEMPL.replace("particledistribution/discrete ", "particledistribution/discrete/massbased ") + "\nfix s all insert/pack seed 67867967 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 5 region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix planeforce": "fix s all planeforce 0 0 1\n" + DUMP,
 "fix print": 'variable sz equal z[1]\nfix s all print 5 "z1 = ${sz}" file s.txt',
 "fix property/atom": "fix s all property/atom sval scalar yes no no 0.5\ndump s all custom 10 s.dump id f_s",
 "fix property/atom/timetracer": "fix s all property/atom/timetracer add_region fill check_region_every 1\ndump s all custom 10 s.dump id f_s[1]",
 "fix property/atom/regiontracer/time": "fix s all property/atom/regiontracer/time add_region fill check_region_every 1\ndump s all custom 10 s.dump id f_s[1]",
 "fix property/atom/tracer": "fix s all property/atom/tracer region_mark fill mark_step 5 marker_style dirac check_mark_every 1\ndump s all custom 10 s.dump id f_s",
 "fix property/atom/tracer/stream": TEMPL + "\nfix sface all mesh/surface file face.stl type 1\nfix sins all insert/stream seed 67867967 distributiontemplate pdd nparticles 4 massrate 1 overlapcheck yes vel constant 0 0 -1 insertion_face sface extrude_length 0.01\nfix s all property/atom/tracer/stream mark_step 0 insert_stream sins n_tracer 2 every 5\ndump s all custom 10 s.dump id f_s",
 "fix property/global": "fix s all property/global sglob scalar 1.5\nvariable sv equal f_s\nthermo_style custom step v_sv",
 "fix custom_property/global": "fix s all custom_property/global sglob scalar 1.5\nvariable sv equal f_s\nthermo_style custom step v_sv",
 "fix property/atomtype": "fix s all property/atomtype sprop peratomtype 1.0 2.0\nthermo_style custom step f_s[1] f_s[2]",
 "fix property/atomtypepair": "fix s all property/atomtypepair sprop peratomtypepair 2 1 2 2 1\nthermo_style custom step f_s[1][2]",
 "fix region/variable": "region sr1 block -0.012 0.012 -0.012 0.012 0 0.005 units box\nregion sr2 block -0.012 0.012 -0.012 0.012 0.005 0.04 units box\nfix s all region/variable n_regions 2 times 1e-4 1e-4 regions sr1 sr2",
 "fix rigid": "fix s all rigid single",
 "fix transportequation/scalar": "fix s all transportequation/scalar equation_id sc quantity sq default_value 1 flux_quantity sflux source_quantity ssrc capacity_quantity none\nthermo_style custom step f_s",
 "fix setforce": "group s1 id 1 2 3\nset group s1 omegaz 10\nfix s s1 setforce 0 0 0\nthermo_style custom step f_s[1] f_s[2] f_s[3]\n" + DUMP,
 "fix sph/density/continuity": "fix s all sph/density/continuity",
 "fix sph/density/corr": "fix s all sph/density/corr shepard every 30",
 "fix sph/density/summation": "fix s all sph/density/summation",
 "fix sph/pressure": "fix s all sph/pressure Tait 60000. 1000. 7.",
 "fix spring": "fix s all spring tether 1.0 0 0 0.003 0.0\nthermo_style custom step f_s f_s[1] f_s[3]",
 "fix spring/rg": "fix s all spring/rg 1.0 0.002",
 "fix spring/self": "fix s all spring/self 1.0\nthermo_style custom step f_s",
 "fix store/force": "fix s all store/force\ndump s all custom 10 s.dump id fz f_s[1] f_s[2] f_s[3]",
 "fix store/state": "fix s all store/state 5 x y z vx omegaz\ndump s all custom 10 s.dump id f_s[1] f_s[3] f_s[5]",
 "fix particletemplate/multiplespheres": "fix s all particletemplate/multiplespheres 15485863 atom_type 1 density constant 2500 nspheres 2 ntry 100000 spheres 0 0 0 0.001 0.001 0 0 0.001\nfix sd all particledistribution/discrete 32452843 1 s 1.0\nregion sins block -0.008 0.008 -0.008 0.008 0.015 0.035 units box\nfix si all insert/pack seed 67867967 distributiontemplate sd insert_every once overlapcheck yes particles_in_region 3 region sins ntry_mc 10000",
 "fix particletemplate/multisphere": "fix s all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 2 ntry 100000 spheres 0 0 0 0.001 0.001 0 0 0.001 type 1\nfix sd all particledistribution/discrete 32452843 1 s 1.0\nregion sins block -0.008 0.008 -0.008 0.008 0.015 0.035 units box\nfix si all insert/pack seed 67867967 distributiontemplate sd insert_every once overlapcheck yes particles_in_region 3 region sins ntry_mc 10000",
 "fix particletemplate/sphere": TEMPL + "\nfix s all insert/pack seed 67867967 distributiontemplate pdd insert_every once overlapcheck yes particles_in_region 5 region sins ntry_mc 10000\nthermo_style custom step atoms",
 "fix viscous": "fix s all viscous 0.001\n" + DUMP,
 "fix wall/gran": "fix s all wall/gran model hooke tangential history primitive type 1 zplane 0.0",
 "fix wall/region": "region sw block -0.012 0.012 -0.012 0.012 0 0.04 units box\nfix s all wall/region sw lj93 1.0 1.0 2.5",
 "fix wall/region/sph": "region sw block -0.012 0.012 -0.012 0.012 0 0.04 units box\nfix s all wall/region/sph sw 0.01 2.5",
 "fix wall/sph": "fix s all wall/sph zplane 0.0 NULL 0.001 1",

 # ---------------- compute styles ----------------
 "compute atom/molecule": "compute ska all ke/atom\ncompute s all atom/molecule c_ska\nfix sa all ave/time 10 1 10 c_s mode vector file s.txt",
 "compute bond/local": "compute s all bond/local dist\ndump s all local 10 s.dump c_s",
 "compute centro/atom": "compute s all centro/atom fcc\ndump s all custom 10 s.dump id c_s",
 "compute cluster/atom": "compute s all cluster/atom 0.004\ndump s all custom 10 s.dump id c_s",
 "compute cna/atom": "compute s all cna/atom 0.004\ndump s all custom 10 s.dump id c_s",
 "compute com": "compute s all com\n" + TH + "c_s[1] c_s[2] c_s[3]",
 "compute com/molecule": "compute s all com/molecule\nfix sa all ave/time 10 1 10 c_s mode vector file s.txt",
 "compute contact/atom": "compute s all contact/atom\ndump s all custom 10 s.dump id c_s",
 "compute contact/atom/gran": "compute s all contact/atom/gran\ndump s all custom 10 s.dump id c_s",
 "compute coord/atom": "compute s all coord/atom 0.004\ndump s all custom 10 s.dump id c_s",
 "compute displace/atom": "compute s all displace/atom\ndump s all custom 10 s.dump id c_s[1] c_s[2] c_s[3] c_s[4]",
 "compute erotate": "compute s all erotate\n" + TH + "c_s",
 "compute erotate/asphere": "compute s all erotate/asphere\n" + TH + "c_s",
 "compute erotate/multisphere": "compute s all erotate/multisphere\n" + TH + "c_s",
 "compute erotate/sphere": "compute s all erotate/sphere\n" + TH + "c_s",
 "compute erotate/sphere/atom": "compute s all erotate/sphere/atom\ndump s all custom 10 s.dump id c_s",
 "compute group/group": "group s1 id <= 9\ngroup s2 id > 9\ncompute s s1 group/group s2\n" + TH + "c_s c_s[1] c_s[2] c_s[3]",
 "compute gyration": "compute s all gyration\n" + TH + "c_s",
 "compute gyration/molecule": "compute s all gyration/molecule\nfix sa all ave/time 10 1 10 c_s mode vector file s.txt",
 "compute inertia/molecule": "compute s all inertia/molecule\nfix sa all ave/time 10 1 10 c_s[1] mode vector file s.txt",
 "compute ke": "compute s all ke\n" + TH + "c_s",
 "compute ke/atom": "compute s all ke/atom\ncompute s2 all reduce sum c_s\n" + TH + "c_s2\ndump s all custom 10 s.dump id c_s",
 "compute ke/multisphere": "compute s all ke/multisphere\n" + TH + "c_s",
 "compute msd": "compute s all msd\n" + TH + "c_s[1] c_s[2] c_s[3] c_s[4]",
 "compute msd/molecule": "compute s all msd/molecule\nfix sa all ave/time 10 1 10 c_s[4] mode vector file s.txt",
 "compute nparticles/tracer/region": "region sr block INF INF INF INF 0 0.005 units box\nfix str all property/atom/tracer region_mark sr mark_step 1\ncompute s all nparticles/tracer/region region_count sr tracer str\n" + TH + "c_s[1] c_s[2] c_s[3] c_s[4]",
 "compute pair/gran/local": "compute s all pair/gran/local pos force\ndump s all local 10 s.dump c_s[1] c_s[2]",
 "compute wall/gran/local": "compute s all wall/gran/local pos force\ndump s all local 10 s.dump c_s[1] c_s[2]",
 "compute pe": "compute s all pe\nfix_modify g energy yes\n" + TH + "c_s",
 "compute pe/atom": "compute s all pe/atom\ncompute s2 all reduce sum c_s\n" + TH + "c_s2",
 "compute pressure": "compute st all temp\ncompute s all pressure st\ncompute s2 all pressure st virial\n" + TH + "c_s c_s2 c_s2[3]",
 "compute property/atom": "compute s all property/atom radius mass omegax omegay omegaz tqx\ndump s all custom 10 s.dump id c_s[1] c_s[2] c_s[3] c_s[6]",
 "compute property/local": "compute s all property/local patom1 patom2\ndump s all local 10 s.dump c_s[1] c_s[2]",
 "compute property/molecule": "compute s all property/molecule mol\nfix sa all ave/time 10 1 10 c_s mode vector file s.txt",
 "compute rdf": "compute s all rdf 20\nfix sa all ave/time 10 1 10 c_s mode vector file s.txt",
 "compute reduce": "compute s all reduce max vz z\ncompute sk all ke/atom\ncompute s3 all reduce sum c_sk\n" + TH + "c_s[1] c_s[2] c_s3",
 "compute reduce/sph": "compute s all reduce/sph sum vz\n" + TH + "c_s",
 "compute reduce/region": "region sr block INF INF INF INF 0 0.005 units box\ncompute sk all ke/atom\ncompute s all reduce/region sr sum c_sk\n" + TH + "c_s",
 "compute rigid": "compute s all rigid property xcm\n" + TH + "c_s[1]",
 "compute multisphere": "compute s all multisphere property xcm\n" + TH + "c_s[1]",
 "compute multisphere/single": "compute s all multisphere/single id 1 property xcm\n" + TH + "c_s[1]",
 "compute slice": "compute sm all msd\ncompute s all slice 1 4 1 c_sm\n" + TH + "c_s[1] c_s[2]",
 "compute stress/atom": "compute s all stress/atom\ncompute sr all reduce sum c_s[1] c_s[3]\ncompute st all temp\ncompute sp all pressure st virial\n" + TH + "c_sr[1] c_sr[2] c_sp[1] c_sp[3]",
 "compute temp": "compute s all temp\n" + TH + "c_s",
 # ---------------- region styles (centre inside: count, group, delete) ----------------
 "region block": "region s block -0.004 0.004 -0.004 0.004 0 0.005 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region cone": "region s cone z 0 0 0.001 0.004 0 0.005 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region cylinder": "region s cylinder z 0 0 0.002 0 0.01 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region intersect": "region s1 block -0.004 0.004 -0.004 0.004 0 0.01 units box\nregion s2 sphere 0 0 0.004 0.004 units box\nregion s intersect 2 s1 s2\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region mesh/tet": "region s mesh/tet file tet.vtk scale 1 move 0 0 0 rotate 0 0 0 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region plane": "region s plane 0 0 0.005 0 0 -1 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region prism": "region s prism -0.004 0.004 -0.004 0.004 0 0.005 0.001 0 0 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region sphere": "region s sphere 0 0 0.005 0.003 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region union": "region s1 block -0.004 0.004 -0.004 0.004 0 0.004 units box\nregion s2 sphere 0.0033 0.0033 0.0066 0.001 units box\nregion s union 2 s1 s2\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 "region wedge": "region s wedge axis z center 0 0 radius 0.006 bounds 0 0.01 angle0 0 angle 90 units box\ngroup s region s\nvariable sn equal count(all,s)\n" + TH + "v_sn\nrun 10\ndelete_atoms region s\nrun 10",
 # ---------------- dump styles ----------------
 "dump atom/vtk": "dump s all atom/vtk 10 s*.vtk",
 "dump custom": "dump s all custom 10 s.dump id type x y z vx radius mass omegaz f_shapes[2]",
 "dump custom/vtk": "dump s all custom/vtk 10 s*.vtk id type x y z vx radius mass omegax",
 "dump custom/vtm": "dump s all custom/vtm 10 s*.vtm particle_properties id type radius mass meshes cad",
 "dump decomposition/vtk": "dump s all decomposition/vtk 10 s*.vtk",
 "dump euler/vtk": "fix se all ave/euler nevery 5 cell_size_relative 2 parallel no\ndump s all euler/vtk 10 s*.vtk",
 "dump image": "dump s all image 10 s*.ppm type type",
 "dump local": "compute sc all tri/contact/local pos force\ndump s all local 10 s.dump index c_sc[1] c_sc[3] c_sc[7] c_sc[9]",
 "dump local/gran/vtk": "compute s all pair/gran/local pos force\ndump s all local/gran/vtk 10 s*.vtp s",
 "dump mesh/stl": "dump s all mesh/stl 10 s*.stl cad",
 "dump stl": "dump s all stl 10 s*.stl cad",
 "dump mesh/vtk": "dump s all mesh/vtk 10 s*.vtk stress id area cad",
 "dump mesh/vtk:stress": "unfix walls\nunfix cad\nfix cad all mesh/surface/stress file plane.stl type 1\nfix walls all tri/wall model hooke mesh cad\ndump s all mesh/vtk 500 s*.vtk stress cad\n" + TH + "f_cad[3]\nthermo 500\nrun 3000",
 "dump mesh/gran/VTK": "dump s all mesh/gran/VTK 10 s*.vtk stress wear cad",
 "dump mesh/vtm": "dump s all mesh/vtm 10 s*.vtm meshes cad mesh_properties stress area",
 "dump movie": "dump s all movie 10 s.mpg type type",
 "dump xyz": "dump s all xyz 10 s.xyz",
 # ---------------- command styles ----------------
 "command change_box": CHK + "\nrun 10\nchange_box all z final 0 0.05 units box\nrun 10",
 "command change_box:remap": CHK + "\nrun 10\nchange_box all x scale 1.1 y scale 1.1 remap units box\nrun 10",
 "command create_atoms": CHK + "\nrun 10\ncreate_atoms 2 single 0 0 0.016 units box\nrun 10",
 "command create_atoms:region": CHK + "\nrun 10\nregion snew block -0.006 0.006 -0.006 0.006 0.012 0.018 units box\ncreate_atoms 1 region snew\nrun 10",
 "command create_box": "",  # the base deck creates its box
 "command delete_atoms": CHK + "\nrun 10\nregion sd block 0 INF INF INF INF INF units box\ndelete_atoms region sd\nrun 10",
 "command delete_atoms:overlap": CHK + "\nrun 10\ndelete_atoms overlap 0.0034 all all\nrun 10",
 "command delete_atoms:group": CHK + "\nrun 10\ngroup sg id 1 5 9\ndelete_atoms group sg compress yes\nrun 10",
 "command delete_bonds": "run 10\ndelete_bonds all multi remove\nrun 10",
 "command displace_atoms": CHK + "\nrun 10\ndisplace_atoms all move 0 0 0.002 units box\nrun 10",
 "command displace_atoms:rotate": CHK + "\nrun 10\ndisplace_atoms all rotate 0 0 0.005 0 0 1 90 units box\nrun 10",
 "command info": "run 10\ninfo system computes dumps fixes groups regions\nrun 10",
 "command minimize": CHK + "\ncompute thermo_pe all pe\nrun 10\nminimize 1e-6 1e-8 20 100\nrun 10",
 "command neigh_modify": "neigh_modify every 1 delay 0 check yes\nrun 10\nneigh_modify one 2000 page 200000\nrun 10",
 "command neigh_modify:exclude": "compute st all tri/stats\nneigh_modify exclude type 1 1\n" + TH + "c_st[1]\nrun 400",
 "command read_data": CHK + "\nrun 10\nread_data add.data add\nrun 10",
 "command read_dump": CHK + "\nrun 10\nwrite_dump all custom s.dump id type x y z vx vy vz radius\nrun 10\nread_dump s.dump 10 x y z vx vy vz radius replace yes\nrun 10",
 "command read_dump:add": CHK + "\nrun 10\nwrite_dump all custom s.dump id type x y z radius\ndisplace_atoms all move 0 0 0.008 units box\nread_dump s.dump 10 x y z radius add yes replace no\nrun 10",
 # read_restart in a fresh deck: clear, then read and redefine the fixes with the same IDs
 "command read_restart": CHK + "\nrun 10\nwrite_restart s.restart\nclear\n" + resumed_base("s.restart") + CHK.replace("chk.dump", "chk2.dump") + "\nrun 10",
 "command replicate": CHK + "\nrun 10\nreplicate 2 1 1 offset 0.024 0 0 shift 0 0 0\nrun 10",
 "command rotate": "run 10\nrotate all 0 0 1 90\nrun 10",
 "command run": "run 10\nrun 10 upto\nrun 10 pre no post no",
 "command run_time": "run_time 1e-4\nrun_time 2e-4 upto",
 "command set:diameter": CHK + "\nrun 10\nset group all diameter 0.001\nrun 10",
 "command set:mass": CHK + "\nrun 10\nset group all mass 1e-3\nrun 10",
 "command set:density": CHK + "\nrun 10\nset group all density 500\nrun 10",
 "command set:omega": CHK + "\nrun 10\nset group all omegaz 50\nrun 10",
 "command set:vel": CHK + "\nrun 10\nset group all vz -0.5\nrun 10",
 "command set:type": CHK + "\nrun 10\nset type 1 type/fraction 2 0.5 12345\nrun 10",
 "command set:xyz": CHK + "\nrun 10\nset atom 1 z 0.02\nrun 10",
 "command velocity": CHK + "\nrun 10\nvelocity all set 0.1 0 0 sum yes\nrun 10\nvelocity all ramp vx 0 0.05 z 0 0.01 units box\nrun 10\nvelocity all zero angular\nvelocity all zero linear\nrun 10",
 "command write_data": CHK + "\nrun 10\nwrite_data s.data\nrun 10",
 "command write_dump": "run 10\nwrite_dump all custom s.dump id type x y z radius mass f_shapes[1]\nrun 10",
 "command write_restart": CHK + "\nrun 10\nwrite_restart s.restart\nrun 10",
 # ---------------- integrate styles ----------------
 "run_style verlet": "run_style verlet\n" + CHK,
 "run_style respa": "run_style respa 2 2\n" + CHK,
 # ---------------- pair styles ----------------
 "pair_style gran": "pair_style gran model hooke tangential history\npair_coeff * *",
 "pair_style bubble": "pair_style bubble model hooke tangential history\npair_coeff * *",
 "pair_style gran_bubble": "pair_style gran_bubble model hooke tangential history\npair_coeff * *",
 "pair_style hybrid": "pair_style hybrid tri/gran model hooke soft 0.004\npair_coeff 1 1 tri/gran\npair_coeff 1 2 tri/gran\npair_coeff 2 2 soft 1.0",
 "pair_style hybrid/overlay": "pair_style hybrid/overlay tri/gran model hooke soft 0.004\npair_coeff * * tri/gran\npair_coeff * * soft 1.0",
 "pair_style line/lj": "pair_style line/lj 0.004\npair_coeff * * 1.0 0.002",
 "pair_style soft": "pair_style soft 0.004\npair_coeff * * 1.0",
 "pair_style sph/artVisc/tensCorr": "pair_style sph/artVisc/tensCorr cubicspline 0.002 artVisc tensCorr\npair_coeff * *",
 "atom_style atomic": {"atom_style": "atomic"},
 "atom_style charge": {"atom_style": "charge"},
 "atom_style ellipsoid": {"atom_style": "ellipsoid"},
 "atom_style full": {"atom_style": "full"},
 "atom_style line": {"atom_style": "line"},
 "atom_style molecular": {"atom_style": "molecular"},
 "atom_style sph": {"atom_style": "sph"},
 "atom_style sph/var": {"atom_style": "sph/var"},
 "atom_style tri": {"atom_style": "tri"},
 "atom_style sphere": {"atom_style": "sphere"},
 "atom_style granular": {"atom_style": "granular"},
 "atom_style hybrid": {"atom_style": "hybrid sphere charge"},
 "pair gran model edinburgh": {"pair_style": "tri/gran model edinburgh"},
 "pair gran model edinburgh/stiffness": {"pair_style": "tri/gran model edinburgh/stiffness"},
 "pair gran model hertz": {"pair_style": "tri/gran model hertz"},
 "pair gran model hertz/stiffness": {"pair_style": "tri/gran model hertz/stiffness"},
 "pair gran model hooke": {"pair_style": "tri/gran model hooke"},
 "pair gran model hooke/hysteresis": {"pair_style": "tri/gran model hooke/hysteresis"},
 "pair gran model hooke/stiffness": {"pair_style": "tri/gran model hooke/stiffness", "lines": "fix k1 all property/global kn peratomtypepair 2 2000 2000 2000 2000\nfix k2 all property/global kt peratomtypepair 2 1000 1000 1000 1000\nfix k3 all property/global gamman peratomtypepair 2 1 1 1 1\nfix k4 all property/global gammat peratomtypepair 2 1 1 1 1"},
 "pair gran model luding": {"pair_style": "tri/gran model luding"},
 "pair gran model thornton_ning": {"pair_style": "tri/gran model thornton_ning"},
 "pair gran tangential history": {"pair_style": "tri/gran model hooke tangential history"},
 "pair gran tangential tan_luding": {"pair_style": "tri/gran model hooke tangential tan_luding"},
 "pair gran tangential no_history": {"pair_style": "tri/gran model hooke tangential no_history"},
 "pair gran cohesion easo/capillary/viscous": {"pair_style": "tri/gran model hooke cohesion easo/capillary/viscous"},
 "pair gran cohesion sjkr": {"pair_style": "tri/gran model hooke cohesion sjkr"},
 "pair gran cohesion sjkr2": {"pair_style": "tri/gran model hooke cohesion sjkr2"},
 "pair gran cohesion washino/capillary/viscous": {"pair_style": "tri/gran model hooke cohesion washino/capillary/viscous"},
 "pair gran rolling_friction cdt": {"pair_style": "tri/gran model hooke rolling_friction cdt"},
 "pair gran rolling_friction epsd": {"pair_style": "tri/gran model hooke rolling_friction epsd"},
 "pair gran rolling_friction epsd2": {"pair_style": "tri/gran model hooke rolling_friction epsd2"},
 "pair gran rolling_friction epsd3": {"pair_style": "tri/gran model hooke rolling_friction epsd3"},
 "pair gran rolling_friction luding": {"pair_style": "tri/gran model hooke rolling_friction luding"},
 "pair gran surface default": {"pair_style": "tri/gran model hooke surface default"},
 "pair gran surface multicontact": {"pair_style": "tri/gran model hooke surface multicontact"},
 "pair gran surface superquadric": {"pair_style": "tri/gran model hooke surface superquadric"},
}

# Decks that take the plugin's styles apart between runs, as a deck may: each must run or stop
# with the ERROR given (a part of its text), never end in a signal.
SEQUENCES = {
    "unfix the particles": ("run 5\nunfix shapes\nrun 5", "requires fix tri/particles"),
    "define the particles again": (
        "run 5\nfix shapes all tri/particles shape r random ntri 20 size 0.004 seed 2 "
        "density 2500\nrun 5", "cannot be defined again"),
    "a second fix tri/particles": (
        "fix shapes2 all tri/particles shape r random ntri 20 size 0.004 seed 2 density 2500\n"
        "run 5", "Only one fix tri/particles"),
    "unfix a wall's mesh": ("run 5\nunfix cad\nrun 5", "mesh 'cad' was removed"),
    "define a wall's mesh again": ("run 5\nfix cad all mesh/surface file plane.stl type 1\nrun 5",
                                   "ERROR"),
    "unfix a wall and its mesh": ("run 5\nunfix walls\nunfix cad\nrun 5", None),
    "unfix the integrator": ("run 5\nunfix integr\nrun 5", None),
    "define the wall again": ("run 5\nfix walls all tri/wall model hooke mesh cad\nrun 5", None),
    "define the integrator again": ("run 5\nfix integr all tri/nve\nrun 5", None),
    "no pair style": ("run 5\npair_style none\nrun 5", None),
    "another pair model": ("run 5\npair_style tri/gran model hertz\npair_coeff * *\nrun 5", None),
    "delete every particle": ("run 5\ndelete_atoms group all\nrun 5", None),
    "delete some particles": ("run 5\ngroup low id <= 5\ndelete_atoms group low\nrun 5", None),
    "integrators by group": ("group low id <= 5\ngroup high id > 5\nunfix integr\n"
                             "fix i1 low tri/nve\nfix i2 high tri/nve\nrun 5", None),
    "a new time step": ("run 5\ntimestep 2e-5\nrun 5", None),
    "runs of no steps": ("run 0\nrun 0\nrun 5", None),
    "a box made larger": ("run 5\nchange_box all x final -0.015 0.015 remap units box\nrun 5", None),
    "a box made closed": ("run 5\nchange_box all boundary f f f\nrun 5", None),
}
