#!/bin/bash
# Bad input: every case must end with exactly one line on stderr that names
# the parameter (or the file, or the cause) and contains the expected text,
# a non-zero exit status, and no output file.
# usage: bad_input.sh AMFRAC WORKDIR [BATCH]
# With BATCH (app_bad_input_batch), the expect cases run at the end in one
# process through the function the executable runs (0.4 s of start-up
# less per case); the other cases always run the executable.
set -u
amfrac=$1 work=$2 batch=${3:-}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
failures=0

# A valid small scene; each case appends or replaces lines.
base='set Dimension = 3
subsection Geometry
  set Stacking sequence = [0/90]s
  set Elements along length = 2
  set Elements along width = 2
end
subsection Output
  set Directory = out
end'

# expect NAME EXPECTED-TEXT PRM-TEXT
queued_names=() queued_texts=()
expect() {
  local name=$1 expected=$2 text=$3
  printf '%s\n' "$text" > "$name.prm"
  if [ -n "$batch" ]; then
    queued_names+=("$name") queued_texts+=("$expected")
    return
  fi
  "$amfrac" "$name.prm" > "$name.stdout" 2> "$name.stderr"
  echo $? > "$name.status"
  find out -type f 2>/dev/null | head -1 | tr -d '\n' > "$name.written"
  rm -rf out
  judge "$name" "$expected"
}

# judge NAME EXPECTED-TEXT: from NAME.status, .stderr and .written.
judge() {
  local name=$1 expected=$2 status lines written
  status=$(cat "$name.status" 2>/dev/null || echo missing)
  lines=$(wc -l < "$name.stderr" 2>/dev/null || echo 0)
  # Input errors stop before the output folder exists; a singular solve
  # stops before any file is written into it.
  written=$(cat "$name.written" 2>/dev/null || echo "(no record)")
  if [ "$status" = missing ] || [ "$status" -eq 0 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$expected" "$name.stderr" || [ -n "$written" ]; then
    echo "FAIL $name: status $status, $lines stderr line(s), written: '$written'; expected '$expected' in:"
    cat "$name.stderr"
    failures=$((failures + 1))
  else
    echo "ok   $name: $(cat "$name.stderr")"
  fi
}

with() { # replace the line matching $1 in the base scene by $2
  printf '%s\n' "$base" | sed "s|$1|$2|"
}

expect unknown_section "Geometri" "$base
subsection Geometri
  set Length = 3
end"
expect unknown_entry "Lenght" "$(with 'set Elements along width = 2' 'set Lenght = 2')"
expect malformed_value "Length" "$(with 'set Elements along width = 2' 'set Length = abc')"
expect malformed_stacking "Geometry/Stacking sequence" "$(with '\[0/90\]s' '[0/90')"
expect bad_repeat "Geometry/Stacking sequence" "$(with '\[0/90\]s' '[0_0/90]')"
expect zero_thickness "Geometry/Ply thickness" "$(with 'set Elements along width = 2' 'set Ply thickness = 0')"
expect ply_count "Geometry/Ply thickness" "$(with 'set Elements along width = 2' 'set Ply thickness = 0.1, 0.2')"
expect zero_subdivisions "Elements per ply" "$(with 'set Elements along width = 2' 'set Elements per ply = 0')"
expect negative_length "Geometry/Length" "$(with 'set Elements along width = 2' 'set Length = -1')"
expect not_positive_definite "positive definite" "$base
subsection Materials
  set nu12 = 3.5
end"
expect negative_modulus "E2" "$base
subsection Materials
  set E2 = -10
end"
expect negative_strength "Materials/Yt" "$base
subsection Materials
  set Yt = 0
end"
expect explicit_no_density "Materials/Density" "$base
subsection Materials
  set Density = 0
end
subsection Time
  set Time integration = explicit
end"
expect explicit_step_too_large "Time/Time step" "$base
subsection Time
  set Time integration = explicit
  set Time step = 1
end"
expect patch_outside_face "Boundary conditions/Patch load/Center" "$base
subsection Boundary conditions
  subsection Patch load
    set Face   = z+
    set Center = 50, 50, 0
    set Force  = 100
  end
end"
expect patch_bad_direction "Boundary conditions/Patch load/Direction" "$base
subsection Boundary conditions
  subsection Patch load
    set Face      = z+
    set Direction = down
  end
end"
expect patch_rectangle_size "Boundary conditions/Patch load/Size" "$base
subsection Boundary conditions
  subsection Patch load
    set Face  = z+
    set Shape = rectangle
    set Size  = 1
  end
end"
expect initial_velocity_syntax "Time/Initial velocity" "$base
subsection Materials
  set Density = 1.6e-9
end
subsection Time
  set Time integration = explicit
  set Initial velocity = 0; 0; sin(
end"
expect mass_scaling_and_step "Time/Mass scaling time step" "$base
subsection Time
  set Time integration       = explicit
  set Time step              = 1e-8
  set Mass scaling time step = 2e-8
end"
expect unknown_material "unknown material 'glass'" "$(with '\[0/90\]s' '[0@glass/90]')"
expect face_not_in_2d "Boundary conditions/z-/Type" "$(with 'set Dimension = 3' 'set Dimension = 2')
subsection Boundary conditions
  subsection z-
    set Type = displacement
  end
end"
expect unknown_face "x0" "$base
subsection Boundary conditions
  subsection x0
    set Type = displacement
  end
end"
expect bad_expression "Boundary conditions/z+/Traction" "$base
subsection Boundary conditions
  subsection z+
    set Type = traction
    set Traction = 0; 0; sin(x
  end
end"
expect wrong_component_count "Boundary conditions/x-/Displacement" "$base
subsection Boundary conditions
  subsection x-
    set Type = displacement
    set Displacement = 0; 0
  end
end"
expect point_outside "Output/Point values" "$base
subsection Output
  set Point values = 100, 100, 100
end"
expect bad_type "Type" "$base
subsection Boundary conditions
  subsection x-
    set Type = glue
  end
end"

expect no_support "no face has Type = displacement" "$base"
expect singular "singular" "$base
subsection Boundary conditions
  subsection x-
    set Type = displacement
    set Components = z
  end
  subsection x+
    set Type = traction
    set Traction = 1; 0; 0
  end
end"

# Cohesive interfaces (interface k lies between plies k and k+1; the base
# laminate has 4 plies, so interfaces 0..2).
cohesive() { # a cohesive-interfaces section with the given entries
  printf '%s\nsubsection Cohesive interfaces\n  set Interfaces = all\n%s\nend\n' "$base" "$1"
}
expect interface_missing "Cohesive interfaces/Interfaces>: interface 5 does not exist" "$(cohesive 'set Interfaces = 0, 5')"
expect interface_garbage "Cohesive interfaces/Interfaces" "$(cohesive 'set Interfaces = first')"
expect zero_strength "Cohesive interfaces/Normal strength" "$(cohesive 'set Normal strength = 0')"
expect negative_energy "Cohesive interfaces/Mode II fracture energy" "$(cohesive 'set Mode II fracture energy = -0.5')"
expect gmax_below_g0 "Cohesive interfaces/Mode I fracture energy" "$(cohesive 'set Normal stiffness = 10')"
expect negative_mu "Cohesive interfaces/Friction coefficient" "$(cohesive 'set Friction coefficient = -0.1')"
expect cd_shear_stiffness "Cohesive interfaces/Shear stiffness>: Law = camanho-davila has one penalty" "$(cohesive 'set Law = camanho-davila
  set Shear stiffness = 5e4')"
expect cd_bk_exponent "Cohesive interfaces/BK exponent>: must be positive" "$(cohesive 'set Law = camanho-davila
  set BK exponent = 0')"
expect cd_law_name "Law" "$(cohesive 'set Law = camanho')"
expect precrack_not_cohesive "Cohesive interfaces/Pre-crack interfaces" "$(cohesive 'set Interfaces = 0
  set Pre-crack interfaces = 1
  set Pre-crack region = x < 1')"
expect precrack_everything "Cohesive interfaces/Pre-crack region>: covers every point" "$(cohesive 'set Pre-crack interfaces = 0, 1, 2
  set Pre-crack region = 1')"
expect precrack_expression "Cohesive interfaces/Pre-crack region" "$(cohesive 'set Pre-crack interfaces = 1
  set Pre-crack region = x <')"
expect bad_control "Control" "$base
subsection Nonlinear solver
  set Control = arc-length
end"
expect zero_opening_increment "Nonlinear solver/Opening increment" "$base
subsection Nonlinear solver
  set Control = opening
  set Opening increment = 0
end"
expect dissipation_with_loads "Nonlinear solver/Control" "$(cohesive '')
subsection Nonlinear solver
  set Control = dissipation
end
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
  subsection x+
    set Type = traction
    set Traction = 1; 0; 0
  end
end"

# A pre-crack region that selects nothing is a warning, not an error.
printf '%s\n' "$(cohesive 'set Pre-crack interfaces = 1
  set Pre-crack region = x > 1000')
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
  subsection x+
    set Type = displacement
    set Displacement = 1e-3*t; 0; 0
  end
end" > precrack_nothing.prm
"$amfrac" precrack_nothing.prm > precrack_nothing.stdout 2>&1
status=$?
if [ $status -ne 0 ] || ! grep -q "warning: parameter <Cohesive interfaces/Pre-crack region> selects no point" precrack_nothing.stdout; then
  echo "FAIL precrack_nothing: status $status"; cat precrack_nothing.stdout; failures=$((failures + 1))
else echo "ok   precrack_nothing: warned, ran"; fi
rm -rf out

# The same failures on two MPI ranks end promptly, with the same line.
if command -v mpirun > /dev/null; then
  for name in malformed_stacking singular precrack_everything; do
    timeout 120 mpirun --allow-run-as-root --oversubscribe -np 2 "$amfrac" "$name.prm" > /dev/null 2> "$name.np2.stderr"
    status=$?
    if [ $status -eq 0 ] || [ $status -eq 124 ] || [ "$(grep -c "amfrac: error" "$name.np2.stderr")" -ne 1 ]; then
      echo "FAIL $name on 2 ranks: status $status"; cat "$name.np2.stderr"; failures=$((failures + 1))
    else echo "ok   $name on 2 ranks"; fi
    rm -rf out
  done
fi

# The loading lever (a 3D laminate, thickness axis z).
lever() { # $1: lines inside subsection Boundary conditions
  printf '%s\n' "$base" "subsection Boundary conditions
  subsection x+
    set Type = displacement
  end
$1
end"
}
expect lever_no_hinge "Boundary conditions/Lever/Hinge where" "$(lever '  subsection Lever
    set Hinge face = x-
    set Hinge where = z > 100
    set Saddle face = z+
  end')"
expect lever_no_saddle_face "Boundary conditions/Lever/Saddle face" "$(lever '  subsection Lever
    set Hinge face = x-
  end')"
expect lever_saddle_is_hinge "Boundary conditions/Lever/Saddle where" "$(lever '  subsection Lever
    set Hinge face = z+
    set Saddle face = z+
  end')"
expect lever_on_support "Boundary conditions/Lever" "$(lever '  subsection Lever
    set Hinge face = x-
    set Saddle face = x+
  end')"
expect lever_2d_face "Boundary conditions/Lever/Saddle face" "$(with 'set Dimension = 3' 'set Dimension = 2' | sed '/Elements along width/d')
subsection Boundary conditions
  subsection Lever
    set Hinge face = x-
    set Saddle face = z+
  end
end"

expect comma_components "Boundary conditions/x+/Traction" "$base
subsection Boundary conditions
  subsection x+
    set Type = traction
    set Traction = 1, 0, 0
  end
end"
expect hole_too_large "Geometry/Hole radius" "$(with 'set Elements along width = 2' 'set Hole radius = 5')"
# The 2D model: a hole needs the in-plane model, which has no ply
# interfaces and needs a symmetric stacking (no membrane-bending coupling).
expect hole_cross_section "Geometry/Hole radius" "$(with 'set Dimension = 3' 'set Dimension = 2' | sed 's|set Elements along width = 2|set Hole radius = 2|')"
in_plane=$(with 'set Dimension = 3' 'set Dimension = 2' | sed 's|subsection Geometry|subsection Geometry\n  set 2D model = in-plane|')
expect in_plane_interfaces "Cohesive interfaces/Interfaces" "$in_plane
subsection Cohesive interfaces
  set Interfaces = all
end"
expect in_plane_unsymmetric "Geometry/Stacking sequence" "$(printf '%s\n' "$in_plane" | sed 's|\[0/90\]s|[0/90]|')"
# Unit mistakes: a modulus in Pa, a density in kg/m^3 (the fuzzer's
# E = 1e300 overflowed the element matrices before this check).
expect modulus_in_pascal "Materials/E1" "$base
subsection Materials
  set E1 = 135e9
end"
expect density_in_kg_per_m3 "Materials/Density" "$base
subsection Materials
  set Density = 1600
end"
# The fuzzer's Length = 1e300 overflowed the mapping (a deal.II assertion
# in the debug build, a "singular matrix" in release).
expect length_beyond_a_kilometre "Geometry/Length" "$(with 'set Elements along length = 2' 'set Length = 1e300')"
expect checkpoint_nan_minutes "entry named Every minutes" "$base
subsection Checkpoint
  set Every minutes = nan
end"
expect checkpoint_with_cycles "Checkpoint/Every n steps" "$base
subsection Adaptivity
  set Refinement cycles = 2
end
subsection Checkpoint
  set Every n steps = 1
end"
# Linear buckling: only of a static state with out-of-plane freedom.
buckling='
subsection Buckling
  set Number of modes = 2
end'
expect buckling_in_plane "Buckling/Number of modes" "$in_plane$buckling"
expect buckling_explicit "Buckling/Number of modes" "$base$buckling
subsection Time
  set Time integration = explicit
end"
expect buckling_basis "Buckling/Max basis size" "$base
subsection Buckling
  set Number of modes = 20
  set Max basis size = 20
end"
expect buckling_tolerance "Buckling/Tolerance" "$base
subsection Buckling
  set Number of modes = 1
  set Tolerance = 0
end"
expect adaptivity_target_kelly "Adaptivity/Strategy" "$base
subsection Adaptivity
  set Refinement cycles = 2
  set Estimator = kelly
  set Strategy = error target
end"
expect adaptivity_fractions "Adaptivity/Coarsen fraction" "$base
subsection Adaptivity
  set Refinement cycles = 2
  set Refine fraction = 0.7
  set Coarsen fraction = 0.4
end"
expect adaptivity_interfaces "Adaptivity/Refinement cycles" "$base
subsection Cohesive interfaces
  set Interfaces = all
end
subsection Adaptivity
  set Refinement cycles = 2
end"
expect adaptivity_explicit "Adaptivity/Refinement cycles" "$base
subsection Time
  set Time integration = explicit
end
subsection Adaptivity
  set Refinement cycles = 2
end"
expect explicit_adaptive_fixed_step "Time/Time step" "$base
subsection Time
  set Time integration = explicit
  set Time step = 1e-9
end
subsection Adaptivity
  set Refine every = 1
end"
expect explicit_adaptive_mass_scaling "Time/Mass scaling time step" "$base
subsection Time
  set Time integration = explicit
  set Mass scaling time step = 1e-7
end
subsection Adaptivity
  set Refine every = 1
end"
expect explicit_adaptive_cracks "Crack insertion/Criterion" "$base
subsection Time
  set Time integration = explicit
end
subsection Crack insertion
  set Criterion = hoffman
end
subsection Adaptivity
  set Refine every = 1
end"
impactor='subsection Impactor
  set Face = z+
  set Center = 0.5, 0.5, 8
end'
explicit='subsection Time
  set Time integration = explicit
end'
expect impactor_static "Impactor/Motion" "$base
$impactor"
prescribed='subsection Impactor
  set Motion = prescribed
end'
# Friction and the prescribed path of the sphere.
expect impactor_path_free "Impactor/Path" "$base
$impactor
$explicit
subsection Impactor
  set Path = 0; 0; -t
end"
expect impactor_path_count "Impactor/Path" "$base
$impactor
$prescribed
subsection Impactor
  set Path = 0; -t
end"
expect impactor_path_malformed "Impactor/Path" "$base
$impactor
$prescribed
subsection Impactor
  set Path = 0; 0; -t*(
end"
# A path that is not finite at t = 0 (static: the load parameter) or
# just after it (explicit: the first row's velocity).
expect impactor_path_infinite "centre is not finite at t = 0 (" "$base
$impactor
$prescribed
subsection Boundary conditions
  subsection z-
    set Type = displacement
  end
end
subsection Impactor
  set Path = 0; 0; 1/t
end"
expect impactor_path_infinite_explicit "centre is not finite at t = 1e-09 s" "$base
$impactor
$prescribed
$explicit
subsection Impactor
  set Path = 0; 0; 1/(t - 1e-9)
end"
expect impactor_guided_velocity "Impactor/Velocity" "$base
$impactor
$explicit
subsection Impactor
  set Velocity = 1000, 0, -10000
end"
# A cylinder lies on the face: its axis in the face's plane, not zero.
expect impactor_cylinder_axis_normal "Impactor/Axis" "$base
$impactor
$prescribed
subsection Impactor
  set Shape = cylinder
  set Axis = 0, 1, 1
end"
expect impactor_cylinder_axis_zero "Impactor/Axis" "$base
$impactor
$prescribed
subsection Impactor
  set Shape = cylinder
  set Axis = 0, 0, 0
end"
expect impactor_shape "Shape" "$base
$impactor
subsection Impactor
  set Shape = cone
end"
expect impactor_stick_factor "Impactor/Tangential penalty factor" "$base
$impactor
$prescribed
subsection Impactor
  set Friction coefficient = 0.3
  set Tangential penalty factor = 0
end"
expect impactor_prescribed_overlap "Impactor/Center" "$base
$impactor
$prescribed
subsection Impactor
  set Center = 0.5, 0.5, 5
end
subsection Boundary conditions
  subsection z-
    set Type = displacement
  end
end"
expect impactor_prescribed_dissipation "Nonlinear solver/Control" "$base
$impactor
$prescribed
subsection Nonlinear solver
  set Control = dissipation
end"
expect impactor_prescribed_buckling "Buckling/Number of modes" "$base
$impactor
$prescribed
subsection Buckling
  set Number of modes = 2
end"
expect impactor_prescribed_cycles "Adaptivity/Refinement cycles" "$base
$impactor
$prescribed
subsection Adaptivity
  set Refinement cycles = 1
end"
expect impactor_2d "Impactor/Face" "$(with 'set Dimension = 3' 'set Dimension = 2')
$impactor
$explicit"
expect impactor_2d_face "Impactor/Face" "$(with 'set Dimension = 3' 'set Dimension = 2')
$impactor
$prescribed"
expect impactor_in_plane "Impactor/Face" "$(with 'set Dimension = 3' 'set Dimension = 2')
subsection Geometry
  set 2D model = in-plane
end
subsection Impactor
  set Face = y+
  set Motion = prescribed
end"
expect impactor_mass "Impactor/Mass" "$base
$impactor
$explicit
subsection Impactor
  set Mass = 0
end"
expect impactor_overlap "Impactor/Center" "$base
$impactor
$explicit
subsection Impactor
  set Center = 0.5, 0.5, 5
end"
expect impactor_center "Center" "$base
$impactor
$explicit
subsection Impactor
  set Center = 0, 0
end"
contact='subsection Contact
  set Enable = true
end'
static_contact="$base
subsection Boundary conditions
  subsection z-
    set Type = displacement
  end
end
$contact"
expect contact_static_dissipation "Nonlinear solver/Control" "$static_contact
subsection Cohesive interfaces
  set Interfaces = 1
end
subsection Nonlinear solver
  set Control = dissipation
end"
expect contact_static_buckling "Buckling/Number of modes" "$static_contact
subsection Buckling
  set Number of modes = 2
end"
expect contact_static_cycles "Adaptivity/Refinement cycles" "$static_contact
subsection Adaptivity
  set Refinement cycles = 2
end"
expect contact_unbonded_disabled "Contact/Unbonded interfaces" "$base
$explicit
subsection Contact
  set Unbonded interfaces = 1
end"
expect contact_unbonded_index "Contact/Unbonded interfaces" "$base
$explicit
$contact
subsection Contact
  set Unbonded interfaces = 7
end"
expect contact_unbonded_and_cohesive "Contact/Unbonded interfaces" "$base
$explicit
$contact
subsection Contact
  set Unbonded interfaces = 1
end
subsection Cohesive interfaces
  set Interfaces = all
end"
expect contact_q2 "Contact/Enable" "$base
$explicit
$contact
subsection Discretization
  set Finite element degree = 2
end"
expect contact_static_finite_strain_adaptive "Contact/Enable" "$static_contact
set Kinematics = total Lagrangian
subsection Adaptivity
  set Refine every = 1
end"
expect contact_unbonded_in_plane "Contact/Unbonded interfaces" "$(with 'set Dimension = 3' 'set Dimension = 2')
$explicit
$contact
subsection Geometry
  set 2D model = in-plane
end
subsection Contact
  set Unbonded interfaces = 1
end"
prism='subsection Geometry
  set Element shape = prism
end'
expect prism_2d "Geometry/Element shape" "$(with 'set Dimension = 3' 'set Dimension = 2')
$prism"
# Interfaces on prisms: P2 needs Gauss points.
expect prism_cohesive_lobatto_p2 "Cohesive interfaces/Quadrature" "$base
$prism
subsection Discretization
  set Finite element degree = 2
end
subsection Cohesive interfaces
  set Interfaces = all
end"
# Contact between the bodies and the impactor on prisms: not yet.
expect prism_contact "a prism mesh cannot be combined yet with Contact/Enable" "$base
$prism
$explicit
$contact"
expect prism_impactor "a prism mesh cannot be combined yet with an impactor" "$base
$prism
$explicit
$impactor"
expect region_time "Geometry/Refinement region" "$base
subsection Geometry
  set Refinement region = x < t
end"
expect prism_region "Geometry/Element shape" "$base
$prism
subsection Geometry
  set Refinement region = x < 2
end"
expect prism_adaptivity_strategy "Adaptivity/Strategy = fixed fraction" "$base
$prism
subsection Adaptivity
  set Refinement cycles = 2
end"
expect prism_adaptivity_refined_box "set Elements per ply instead" "$base
$prism
subsection Geometry
  set Global refinements = 1
end
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = uniform
end"
expect prism_adaptivity_imperfection "adaptivity with a Geometry/Imperfection" "$base
$prism
subsection Geometry
  set Imperfection = 0; 0; 0.01*x
end
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = uniform
end"
expect prism_adaptivity_imperfection_mode "adaptivity with a Geometry/Imperfection mode" "$base
$prism
subsection Geometry
  set Imperfection mode = 1
  set Imperfection amplitude = 0.01
end
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = uniform
end"
expect prism_adaptivity_kelly "Adaptivity/Estimator = kelly" "$base
$prism
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = uniform
  set Estimator = kelly
end"
# The same during a load history: the threshold's remeshing follows
# Strategy too, and every remeshing extrudes the plane.
interfaces='subsection Cohesive interfaces
  set Interfaces = all
end'
expect prism_history_strategy "Adaptivity/Strategy = fixed fraction" "$base
$prism
$interfaces
subsection Adaptivity
  set Error threshold = 0.05
end"
expect prism_process_zone_refined_box "set Elements per ply instead" "$base
$prism
$interfaces
subsection Geometry
  set Global refinements = 1
end
subsection Adaptivity
  set Process zone elements = 2
end"
# The process-zone rule on wedges: its own size field, in the plane, in
# Newton runs.
expect prism_process_zone_with_estimator "Process zone elements together with Refine every" "$base
$prism
$interfaces
subsection Adaptivity
  set Process zone elements = 2
  set Refine every          = 2
end"
expect prism_process_zone_directions "Process zone directions = x or y" "$base
$prism
$interfaces
subsection Adaptivity
  set Process zone elements   = 2
  set Process zone directions = x
end"
expect prism_process_zone_explicit "Process zone elements in an explicit run" "$base
$prism
$explicit
$interfaces
subsection Adaptivity
  set Process zone elements = 2
end"
expect adaptivity_max_cells "Maximum cells" "$base
subsection Adaptivity
  set Maximum cells = -3
end"
expect prism_xdmf "Geometry/Element shape" "$base
$prism
subsection Output
  set Field format = xdmf
end"
expect prism_explicit_q2 "Geometry/Element shape" "$base
$prism
$explicit
subsection Discretization
  set Finite element degree = 2
end"
# Gmsh in-plane meshes (Geometry/Mesh file, relative to the .prm's folder).
mesh() { printf 'subsection Geometry\n  set Mesh file = %s\n%s\nend' "$1" "${2:-}"; }
printf 'Point(1) = {0, 0, 0, 1}\n' > syntax.geo
printf 'Point(1) = {0, 0, 0, 1};\nPoint(2) = {1, 0, 0, 1};\nLine(1) = {1, 2};\n' > curve.geo
square='Point(1) = {0, 0, 0, 0.4}; Point(2) = {1, 0, 0, 0.4};
Point(3) = {1, 1, 0, 0.4}; Point(4) = {0, 1, 0, 0.4};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};'
printf '%s\n' "$square" > square.geo
printf '%s\nRecombine Surface {1};\n' "$square" > square_quads.geo
printf '%s\nPoint(5) = {2, 0, 0, 0.4}; Point(6) = {2, 1, 0, 0.4};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Recombine Surface {2};\n' "$square" > mixed.geo
printf 'Point(1) = {0, 0, 0, 1}; Point(2) = {1, 0, 1, 1}; Point(3) = {0, 1, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Surface(1) = {1};\n' > tilted.geo
echo "not a mesh" > square.txt
expect mesh_file_missing "cannot open" "$base
$(mesh nothere.geo)"
expect mesh_file_extension "neither a .geo nor a .msh" "$base
$(mesh square.txt)"
expect mesh_file_syntax "Gmsh failed" "$base
$(mesh syntax.geo)"
expect mesh_file_no_surface "has no 2D elements" "$base
$(mesh curve.geo)"
expect mesh_file_not_plane "is not in the plane z = 0" "$base
$(mesh tilted.geo)"
expect mesh_file_triangles_on_hexahedra "hexahedron needs a mesh of quadrilaterals" "$base
$(mesh square.geo)"
expect mesh_file_quads_on_prisms "prism needs a mesh of triangles" "$base
$(mesh square_quads.geo '  set Element shape = prism')"
expect mesh_file_mixed "mixed prism/hexahedron meshes" "$base
$(mesh mixed.geo '  set Element shape = prism')"
expect mesh_file_2d "Geometry/Mesh file" "$(with 'set Dimension = 3' 'set Dimension = 2')
$(mesh square.geo)"
expect mesh_file_edge_grading "Geometry/Edge grading" "$base
$(mesh square_quads.geo '  set Edge grading = 4')"
expect mesh_file_hole "a hole belongs in the mesh file" "$base
$(mesh square.geo '  set Hole radius = 0.1')"
# A condition on a side that the file does not name (it names x- only).
printf '%s\nPhysical Curve("x-") = {4};\n' "$square" > square_x.geo
expect mesh_file_missing_side "Boundary conditions/y-/Type" "$base
$(mesh square_x.geo '  set Element shape = prism')
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
  subsection y-
    set Type = displacement
  end
end"
expect mesh_file_patch_side "Patch load on a side face" "$base
$(mesh square.geo)
subsection Boundary conditions
  subsection Patch load
    set Face = x-
  end
end"
expect prism_adaptivity_msh "cannot be remeshed: give the .geo" "$base
$(mesh plate.msh '  set Element shape = prism')
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = error target
end"
# 3D mesh files: the plies are physical volumes 'ply 1' .. 'ply 4' of a
# unit square extruded ply by ply (quadrilaterals: hexahedra; triangles:
# wedges; without Layers: tetrahedra).
volume() { # volume N-PLIES RECOMBINE LAYERS
  printf 'Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Line(4) = {4, 1}; Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1 : 4} = 3; Transfinite Surface{1};%s
top = 1;
For p In {1 : %s}
  out[] = Extrude {0, 0, 0.125} { Surface{top}; %s };
  Physical Volume(Sprintf("ply %%g", p)) = {out[1]};
  top = out[0];
EndFor\n' "$2" "$1" "$3"
}
volume 4 ' Recombine Surface{1};' 'Layers{1}; Recombine;' > hexahedra.geo
volume 3 ' Recombine Surface{1};' 'Layers{1}; Recombine;' > three_plies.geo
volume 4 '' 'Layers{1}; Recombine;' > wedges.geo
volume 4 '' '' > tetrahedra.geo
expect volume_missing_ply "has no physical volume named 'ply 4'" "$base
$(mesh three_plies.geo)"
expect volume_tetrahedra "has elements of type 'Tetrahedron 4'" "$base
$(mesh tetrahedra.geo)"
expect volume_shape "Element shape>: prism does not match" "$base
$(mesh hexahedra.geo '  set Element shape = prism')"
expect volume_shape_wedges "Element shape>: hexahedron does not match" "$base
$(mesh wedges.geo)"
expect volume_patch_unnamed "Patch load/Face>: the laminate has no face named 'z+'" "$base
$(mesh hexahedra.geo)
subsection Boundary conditions
  subsection Patch load
    set Face = z+
  end
end"
expect volume_wedges_adaptivity "cannot be combined with adaptivity" "$base
$(mesh wedges.geo '  set Element shape = prism')
subsection Adaptivity
  set Refinement cycles = 2
  set Strategy = error target
end"
# Ply 2 stops at x = 1 and ply 3 lies on ply 1 beyond it: no cohesive
# interface can join plies 1 and 3.
printf 'Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0}; Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Transfinite Curve{1 : 7} = 2; Transfinite Surface{1, 2}; Recombine Surface{1, 2};
a[] = Extrude {0, 0, 0.125} { Surface{1}; Layers{1}; Recombine; };
b[] = Extrude {0, 0, 0.125} { Surface{2}; Layers{1}; Recombine; };
c[] = Extrude {0, 0, 0.125} { Surface{a[0]}; Layers{1}; Recombine; };
d[] = Extrude {0, 0, 0.125} { Surface{c[0]}; Layers{1}; Recombine; };
e[] = Extrude {0, 0, 0.125} { Surface{b[0]}; Layers{1}; Recombine; };
Physical Volume("ply 1") = {a[1], b[1]};
Physical Volume("ply 2") = {c[1]};
Physical Volume("ply 3") = {d[1], e[1]};\n' > internal_drop.geo
expect volume_unbonded_skipped_interface "Contact/Unbonded interfaces>: ply 1 touches ply 3" "$base
$(mesh internal_drop.geo '  set Stacking sequence = [0/90/0]')
$explicit
$contact
subsection Contact
  set Unbonded interfaces = 1
end"
expect volume_skipped_interface "Cohesive interfaces/Interfaces>: ply 1 touches ply 3" "$base
$(mesh internal_drop.geo '  set Stacking sequence = [0/90/0]')
subsection Cohesive interfaces
  set Interfaces = all
end"
expect contact_penalty "Contact/Penalty" "$base
$explicit
$contact
subsection Contact
  set Penalty = 0
end"
expect adaptivity_history_region "refines one side of cohesive interface" "$base
subsection Geometry
  set Refinement region = z > 0.25
end
subsection Cohesive interfaces
  set Interfaces = all
end
subsection Adaptivity
  set Refine every = 2
end"
expect adaptivity_history_linear "Adaptivity/Process zone elements" "$base
subsection Adaptivity
  set Process zone elements = 2
end"
expect process_zone_y_in_2d "Adaptivity/Process zone directions" "$base
set Dimension = 2
subsection Cohesive interfaces
  set Interfaces = all
end
subsection Adaptivity
  set Process zone elements   = 2
  set Process zone directions = y
end"
expect process_zone_x_with_estimator "Adaptivity/Process zone directions" "$base
subsection Cohesive interfaces
  set Interfaces = all
end
subsection Adaptivity
  set Process zone elements   = 2
  set Process zone directions = x
  set Refine every            = 5
end"

# Total Lagrangian kinematics: what it cannot take yet, and imperfections.
expect tl_explicit "Kinematics" "$base
set Kinematics = total Lagrangian
subsection Time
  set Time integration = explicit
end"
expect buckling_times_order "Buckling/Analysis times" "$base
subsection Buckling
  set Number of modes = 1
  set Analysis times  = 0.5, 0.2
end"
expect buckling_times_past_end "Buckling/Analysis times" "$base
subsection Buckling
  set Number of modes = 1
  set Analysis times  = 0.5, 2
end"
expect buckling_times_no_modes "Buckling/Analysis times" "$base
subsection Buckling
  set Analysis times = 0.5
end"
expect buckling_times_zero "Buckling/Analysis times" "$base
subsection Buckling
  set Number of modes = 1
  set Analysis times  = 0, 0.5
end"
expect buckling_times_cycles "Buckling/Analysis times" "$base
subsection Buckling
  set Number of modes = 1
  set Analysis times  = 0.5
end
subsection Adaptivity
  set Refinement cycles = 1
end"
# The pre-buckled state's analysis follows the load path: loads
# proportional to t only (as for arc-length below).
growing_traction="$base
set Kinematics = total Lagrangian
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
  subsection z+
    set Type = traction
    set Traction = 0; 0; -1-t
  end
end"
expect tl_buckling_not_proportional "Buckling/Number of modes" "$growing_traction
subsection Buckling
  set Number of modes = 1
end"
expect tl_dissipation "Nonlinear solver/Control" "$base
set Kinematics = total Lagrangian
subsection Nonlinear solver
  set Control = dissipation
end"
expect imperfection_syntax "Geometry/Imperfection" "$(with 'set Elements along width = 2' 'set Imperfection = 0; 0; sin(')"
expect imperfection_nan "Geometry/Imperfection" "$(with 'set Elements along width = 2' 'set Imperfection = 0; 0; sqrt(x-1)')"
expect imperfection_count "Geometry/Imperfection" "$(with 'set Elements along width = 2' 'set Imperfection = 0; 0')"

expect arc_length_linear "Nonlinear solver/Control" "$base
subsection Nonlinear solver
  set Control = arc-length
end"
expect arc_length_not_proportional "proportional to t" "$growing_traction
subsection Nonlinear solver
  set Control = arc-length
end"

expect imperfection_mode_amplitude "Geometry/Imperfection amplitude" "$(with 'set Elements along width = 2' 'set Imperfection mode = 1')"
expect imperfection_mode_explicit "Geometry/Imperfection mode" "$base
subsection Geometry
  set Imperfection mode      = 1
  set Imperfection amplitude = 0.1
end
subsection Time
  set Time integration = explicit
end"

# Crack insertion: combinations not available yet, bad plies, bad data.
expect crack_mass_scaling "Time/Mass scaling time step" "$base
subsection Crack insertion
  set Criterion = hoffman
end
subsection Time
  set Time integration       = explicit
  set Mass scaling time step = 1e-7
end"
expect crack_plies "Crack insertion/Plies" "$base
subsection Crack insertion
  set Criterion = hoffman
  set Plies     = 0, 7
end"
expect crack_region "Crack insertion/Region" "$base
subsection Crack insertion
  set Criterion = hoffman
  set Region    = x <
end"
expect crack_strength_scale "Crack insertion/Strength scale" "$base
subsection Boundary conditions
  subsection x-
    set Type = displacement
  end
end
subsection Crack insertion
  set Criterion      = hoffman
  set Strength scale = x - 100
end"
expect crack_toughness "Materials/Gc" "$base
subsection Materials
  set Gc = 0
end"

# A missing file and an unknown option.
"$amfrac" no_such_file.prm > /dev/null 2> missing.stderr
status=$?
if [ $status -eq 0 ] || ! grep -q "cannot open parameter file 'no_such_file.prm'" missing.stderr; then
  echo "FAIL missing_file"; cat missing.stderr; failures=$((failures + 1))
else echo "ok   missing_file: $(cat missing.stderr)"; fi
"$amfrac" --frobnicate > /dev/null 2> option.stderr
status=$?
if [ $status -eq 0 ] || ! grep -q "unknown option" option.stderr; then
  echo "FAIL unknown_option"; failures=$((failures + 1))
else echo "ok   unknown_option"; fi

# An existing output folder is left intact by a rejected run.
mkdir -p out && echo keep > out/history.csv
printf '%s\n' "$(with '\[0/90\]s' '[0/90')" > keep.prm
"$amfrac" keep.prm > /dev/null 2>&1
if [ "$(cat out/history.csv)" != keep ]; then
  echo "FAIL a rejected run touched existing output"; failures=$((failures + 1))
fi
rm -rf out

# A crack whose penalty cannot hold its bilinear law stops the run when it
# is inserted, names the parameter and keeps what was written before.
printf '%s\n' "set Dimension = 2
subsection Geometry
  set Stacking sequence = [90]
  set Ply thickness = 1
  set Length = 4
  set Elements along length = 4
end
subsection Boundary conditions
  subsection x-
    set Type = displacement
    set Components = x, y
    set Displacement = 0; 0
  end
  subsection x+
    set Type = displacement
    set Components = x
    set Displacement = 0.04*t
  end
end
subsection Crack insertion
  set Criterion = hoffman
  set Penalty stiffness = 100
end
subsection Output
  set Directory = out
  set Field format = none
end" > crack_penalty.prm
"$amfrac" crack_penalty.prm > crack_penalty.stdout 2> crack_penalty.stderr
status=$?
if [ $status -eq 0 ] || ! grep -q "Crack insertion/Penalty stiffness" crack_penalty.stderr \
   || [ "$(wc -l < out/history.csv)" -lt 2 ]; then
  echo "FAIL crack_penalty: status $status"; cat crack_penalty.stderr; failures=$((failures + 1))
else echo "ok   crack_penalty: $(cat crack_penalty.stderr)"; fi
rm -rf out

# Plastic plies (Materials/Plasticity = hoffman): malformed entries, and
# the paths they cannot run on yet.
plastic='subsection Materials
  set Plasticity = hoffman
end'
expect plasticity_value "Plasticity" "$base
subsection Materials
  set Plasticity = hofman
end"
expect plasticity_count "Materials/Plasticity" "$base
subsection Materials
  set Names = a, b, c
  set Plasticity = hoffman, none
end"
expect hardening_negative "Hardening" "$base
subsection Materials
  set Hardening = -1
end"
expect plastic_explicit "Materials/Plasticity" "$base
$plastic
subsection Time
  set Time integration = explicit
end"
expect plastic_in_plane "Materials/Plasticity" "set Dimension = 2
subsection Geometry
  set Stacking sequence = [0/90]s
  set 2D model = in-plane
end
$plastic
subsection Output
  set Directory = out
end"
expect plastic_cracks "Materials/Plasticity" "$base
$plastic
subsection Crack insertion
  set Criterion = hoffman
end"
expect plastic_buckling "Materials/Plasticity" "$base
$plastic
subsection Buckling
  set Number of modes = 2
end"
expect plastic_cycles "Materials/Plasticity" "$base
$plastic
subsection Adaptivity
  set Refinement cycles = 2
end"
expect edge_grading_prisms "Geometry/Edge grading" "$base
subsection Geometry
  set Element shape = prism
  set Edge grading = 4
end"
expect edge_grading_hole "Geometry/Edge grading" "$base
subsection Geometry
  set Hole radius = 2
  set Edge grading = 4
end"
expect edge_grading_below_one "Edge grading" "$base
subsection Geometry
  set Edge grading = 0.5
end"
expect max_steps_linear "Nonlinear solver/Maximum steps" "$base
subsection Nonlinear solver
  set Maximum steps = 3
end"
expect plastic_dissipation "Materials/Plasticity" "$base
$plastic
subsection Nonlinear solver
  set Control = dissipation
end"

# A perfectly plastic ply under a traction beyond its limit load has no
# equilibrium: the run stops with the cause, exit status 1, and keeps the
# converged steps.
printf '%s\n' "set Dimension = 3
subsection Geometry
  set Stacking sequence = [90]
  set Ply thickness = 1
  set Length = 1
  set Width = 1
  set Elements along length = 2
  set Elements along width = 2
end
$plastic
subsection Boundary conditions
  subsection x-
    set Type = displacement
    set Components = x
    set Displacement = 0
  end
  subsection x+
    set Type = traction
    set Traction = 80*t; 0; 0
  end
  subsection y-
    set Type = displacement
    set Components = y
    set Displacement = 0
  end
  subsection z-
    set Type = displacement
    set Components = z
    set Displacement = 0
  end
end
subsection Time
  set Number of steps = 8
end
subsection Output
  set Directory = out
  set Field format = none
end" > plastic_limit.prm
"$amfrac" plastic_limit.prm > plastic_limit.stdout 2> plastic_limit.stderr
status=$?
if [ $status -ne 1 ] || ! grep -q "limit load of the plastic plies" plastic_limit.stderr \
   || [ "$(wc -l < plastic_limit.stderr)" -ne 1 ] \
   || [ "$(wc -l < out/history.csv)" -ne 6 ]; then
  echo "FAIL plastic_limit: status $status"; cat plastic_limit.stderr; failures=$((failures + 1))
else echo "ok   plastic_limit: $(cat plastic_limit.stderr)"; fi
rm -rf out

if [ -n "$batch" ]; then
  "$batch" "${queued_names[@]}" || echo "the batch of expect cases ended with status $?"
  for i in "${!queued_names[@]}"; do
    judge "${queued_names[$i]}" "${queued_texts[$i]}"
  done
fi
echo "$failures failure(s)"
[ $failures -eq 0 ]
