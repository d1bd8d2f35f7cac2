#!/usr/bin/env bash
# Compact tension (sequentially linear control): the all-PD run of full_pd.prm, the blended
# coupled run of coupled.prm and the overlapping-Schwarz run of schwarz.prm with the shipped law
# (softening bonds, G_c on the lattice, to 0.85 of the peak), then the all-PD run at other
# lattice spacings and horizons (the convergence of the peak load ratio), the brittle runs of the
# README's analysis (brittle_*: to complete separation), the LEFM comparison and the plots
# load.png and crack.png. Results go to results/ next to this script. The last line is the
# all-PD run's `peak load ratio (PD/LEFM): <value>`.
# usage: bash doc/benchmarks/compact_tension/run.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
rm -rf results
mkdir -p results

# variant SOURCE NAME SED-EXPRESSIONS...: SOURCE.prm with its output directory set to
# results/NAME and the given edits, written to results/NAME/run.prm.
variant() {
  local source=$1 name=$2
  shift 2
  mkdir -p "results/$name"
  sed -e "s|set Directory  = results/.*|set Directory  = results/$name|" "$@" "$source.prm" \
    > "results/$name/run.prm"
}
# The shipped law (full_pd.prm, coupled.prm; issue #40 part 2, README "The shipped law"): softening
# PMB bonds, <Failure law> = linear softening with the ratio n = SOFT_RATIO (default 2) and
# N = SOFT_TEETH saw teeth (default 8), G_c calibrated on the lattice (<Fracture energy
# calibration> = lattice: the bonds a straight crack cuts dissipate exactly the G_c of LEFM); the
# runs end once the load has fallen below 85 % of its peak (<Separation load fraction> = 0.85:
# the peak is what they measure; each saw tooth is an event, and the run to separation,
# the variant full_pd_separated, takes about ten times as long).
law=(-e "s|^    set Softening ratio = 2$|    set Softening ratio = ${SOFT_RATIO:-2}|"
  -e "s|^    set Softening teeth = 8$|    set Softening teeth = ${SOFT_TEETH:-8}|")
# brittle: the files' bonds as they were before (brittle PMB, the continuum calibration), for the
# README's sections up to "Softening bonds" (why the brittle peak rises above LEFM).
# They run to separation (the load below 5 % of its peak).
brittle=(-e "/^    set Fracture energy calibration = lattice$/d" -e "/^    set Failure law     = linear softening$/d"
  -e "/^    set Softening ratio = 2$/d" -e "/^    set Softening teeth = 8$/d"
  -e "s|Separation load fraction = 0.85|Separation load fraction = 0.05|")
separated=(-e "s|Separation load fraction = 0.85|Separation load fraction = 0.05|")
variant full_pd full_pd "${law[@]}"
variant coupled coupled "${law[@]}"
# schwarz.prm includes coupled.prm: its variants include the coupled variant's run.prm instead.
variant schwarz schwarz -e "s|^include coupled.prm$|include results/coupled/run.prm|"
# The shipped law to complete separation (not in the default set: README "The shipped law").
variant full_pd full_pd_separated "${law[@]}" "${separated[@]}"
variant coupled coupled_separated "${law[@]}" "${separated[@]}"
variant schwarz schwarz_separated -e "s|^include coupled.prm$|include results/coupled_separated/run.prm|"
variant full_pd brittle_full_pd "${brittle[@]}"
variant coupled brittle_coupled "${brittle[@]}"
variant schwarz brittle_schwarz -e "s|^include coupled.prm$|include results/brittle_coupled/run.prm|"
# Other lattice spacings: the pin columns are the boxes [0, dx] in x, the anchors the boxes
# [0, dx] x -/+[18 mm, 18 mm + dx] (one particle each).
dx2=(-e "s|Lattice spacing = 1e-3|Lattice spacing = 2e-3|" -e "s|Upper corner = 1e-3,|Upper corner = 2e-3,|"
  -e "s|0\.019$|0.020|")
dx05=(-e "s|Lattice spacing = 1e-3|Lattice spacing = 0.5e-3|" -e "s|Upper corner = 1e-3,|Upper corner = 0.5e-3,|"
  -e "s|0\.019$|0.0185|")
dx04=(-e "s|Lattice spacing = 1e-3|Lattice spacing = 0.4e-3|" -e "s|Upper corner = 1e-3,|Upper corner = 0.4e-3,|"
  -e "s|0\.019$|0.0184|")
# dx = 1.5 mm: 50 mm is no multiple of it; the specimen [-9, 39] x [-24, 24] mm keeps the load
# line at x = dx/2 and the notch tip midway between two particle columns (x = 19.5 mm): W =
# 38.25 mm, a/W = 0.490.
dx15=(-e "s|Lattice spacing = 1e-3|Lattice spacing = 1.5e-3|"
  -e "s|Upper corner = 1e-3,|Upper corner = 1.5e-3,|" -e "s|0\.019$|0.0195|"
  -e "s|-0.010, -0.024|-0.009, -0.024|" -e "s|0.040, 0.024|0.039, 0.024|"
  -e "s|-0.011, 0 : 0.020, 0|-0.010, 0 : 0.0195, 0|")
m2=(-e "s|Horizon factor  = 3.015|Horizon factor  = 2.015|")
m4=(-e "s|Horizon factor  = 3.015|Horizon factor  = 4.015|")
# The brittle runs of the README's section "Why the peak rises above LEFM" (their notches end at
# x_t, which since the pre-crack rule leaves the tie bonds intact).
variant full_pd brittle_dx_2mm "${dx2[@]}" "${brittle[@]}"
variant full_pd brittle_dx_0.5mm "${dx05[@]}" "${brittle[@]}"
variant full_pd brittle_m_4 "${m4[@]}" "${brittle[@]}"
variant full_pd brittle_m_2 "${m2[@]}" "${brittle[@]}"
variant full_pd brittle_dx_1.5mm "${dx15[@]}" "${brittle[@]}"
variant full_pd brittle_dx_1.5mm_m_2 "${dx15[@]}" "${m2[@]}" "${brittle[@]}"
variant full_pd brittle_dx_1.5mm_m_4 "${dx15[@]}" "${m4[@]}" "${brittle[@]}"
variant full_pd brittle_dx_2mm_m_2 "${dx2[@]}" "${m2[@]}" "${brittle[@]}"
variant full_pd brittle_dx_2mm_m_4 "${dx2[@]}" "${m4[@]}" "${brittle[@]}"
# The crack-tip toughness of the lattice: the K-field square of k_field.prm (brittle bonds) for
# m = 2, 3, 4.
variant k_field k_field
variant k_field k_field_m_2 "${m2[@]}"
variant k_field k_field_m_4 "${m4[@]}" \
  -e "s|Maximum events           = 40|Maximum events           = 60|"

# The convergence of the shipped law (README "Converging to LEFM"): full_pd.prm's bonds at
# dx = 2, 1.5, 1, 0.5 mm and m = 3, 4, ending at 0.85 of the peak as the files do. They put the
# notch's end at x_t - 0.01 dx (all ties intact; since the pre-crack rule, doc/theory/models.md
# "Pre-cracks", x_t itself cuts the same bonds: the move is kept so that these runs repeat the
# README's tables exactly; postprocess.py's ASTM load takes a from the moved end). dx_1mm is
# full_pd with the moved notch (the same events and peak).
# notch X_T DX_MM S EPS: the pre-crack's end moved from x_t to x_t + (S + EPS) dx.
notch() {
  echo "s|: $1, 0|: $(awk -v t="$1" -v d="$2" -v s="$3" -v e="$4" 'BEGIN { printf "%.9g", t + (s + e) * d * 1e-3 }'), 0|"
}
variant full_pd dx_2mm "${dx2[@]}" -e "$(notch 0.020 2 0 -0.01)" "${law[@]}"
variant full_pd dx_1.5mm "${dx15[@]}" -e "$(notch 0.0195 1.5 0 -0.01)" "${law[@]}"
variant full_pd dx_1mm -e "$(notch 0.020 1 0 -0.01)" "${law[@]}"
variant full_pd dx_0.5mm "${dx05[@]}" -e "$(notch 0.020 0.5 0 -0.01)" "${law[@]}"
variant full_pd dx_2mm_m_4 "${dx2[@]}" "${m4[@]}" -e "$(notch 0.020 2 0 -0.01)" "${law[@]}"
variant full_pd dx_1.5mm_m_4 "${dx15[@]}" "${m4[@]}" -e "$(notch 0.0195 1.5 0 -0.01)" "${law[@]}" \
 
variant full_pd m_4 "${m4[@]}" -e "$(notch 0.020 1 0 -0.01)" "${law[@]}"
# Not in the default set (it ran 71 min on one rank and was stopped at event 687):
variant full_pd dx_0.5mm_m_4 "${dx05[@]}" "${m4[@]}" -e "$(notch 0.020 0.5 0 -0.01)" "${law[@]}" \
 
# Not in the default set either (2 ranks, 40 min for 224 events; README "Converging to LEFM"):
variant full_pd dx_0.4mm_m_4 "${dx04[@]}" "${m4[@]}" -e "$(notch 0.020 0.4 0 -0.01)" "${law[@]}" \
 
# The LEFM load of the PD specimen itself (compliance.py): the first event only (the elastic state,
# brittle bonds: the law does not enter it), the notch's end at x_t + (s - 0.001) dx, s = -1, 0, 1
# (one column of bonds fewer and more, the ties intact), for dx = 2, 1.5, 1, 0.5 mm and m = 3, 4.
one=(-e "s|Separation load fraction = 0.05|Separation load fraction = 0.05\n    set Maximum events           = 1|"
  -e "s|Write HDF5 = true|Write HDF5 = false|")
compliance=""
for m in 3 4; do
  for s in -1 0 1; do
    mm=(); [ $m = 4 ] && mm=("${m4[@]}")
    variant full_pd "c_2_${m}_$s" "${dx2[@]}" "${mm[@]}" -e "$(notch 0.020 2 $s -0.001)" "${brittle[@]}" "${one[@]}"
    variant full_pd "c_1.5_${m}_$s" "${dx15[@]}" "${mm[@]}" -e "$(notch 0.0195 1.5 $s -0.001)" "${brittle[@]}" \
      "${one[@]}"
    variant full_pd "c_1_${m}_$s" "${mm[@]}" -e "$(notch 0.020 1 $s -0.001)" "${brittle[@]}" "${one[@]}"
    variant full_pd "c_0.5_${m}_$s" "${dx05[@]}" "${mm[@]}" -e "$(notch 0.020 0.5 $s -0.001)" "${brittle[@]}" \
      "${one[@]}"
  done
  for dx in 2 1.5 1 0.5; do compliance="$compliance c_${dx}_${m}_-1 c_${dx}_${m}_0 c_${dx}_${m}_1"; done
done
# The triple of dx_0.4mm_m_4, outside the default set as that run is (CT_RUNS="c_0.4_4_-1 c_0.4_4_0
# c_0.4_4_1"; compliance.py on them gives its P_PD).
for s in -1 0 1; do
  variant full_pd "c_0.4_4_$s" "${dx04[@]}" "${m4[@]}" -e "$(notch 0.020 0.4 $s -0.001)" "${brittle[@]}" "${one[@]}"
done
# The crack-tip toughness with softening bonds: k_field.prm with the shipped law.
soft=(-e "s|^    set Fracture energy = 1000$|    set Fracture energy = 1000\n    set Fracture energy calibration = lattice\n    set Failure law     = linear softening\n    set Softening ratio = ${SOFT_RATIO:-2}\n    set Softening teeth = ${SOFT_TEETH:-8}|")
variant k_field soft_k_field "${soft[@]}" -e "s|Maximum events           = 40|Maximum events           = 400|"
variant k_field soft_k_field_m_2 "${m2[@]}" "${soft[@]}" \
  -e "s|Maximum events           = 40|Maximum events           = 200|"
variant k_field soft_k_field_m_4 "${m4[@]}" "${soft[@]}" \
  -e "s|Maximum events           = 40|Maximum events           = 450|"

# The finest runs (dx = 0.5 mm) last, as they take longest; CT_RUNS="..." runs a subset (also the
# variants outside the default set: full_pd_separated, coupled_separated, schwarz_separated,
# brittle_coupled, brittle_schwarz, dx_0.5mm_m_4).
all="full_pd coupled schwarz brittle_full_pd brittle_dx_2mm brittle_m_2 brittle_m_4"
all="$all brittle_dx_2mm_m_2 brittle_dx_2mm_m_4 brittle_dx_1.5mm brittle_dx_1.5mm_m_2"
all="$all brittle_dx_1.5mm_m_4 k_field k_field_m_2 k_field_m_4 dx_2mm dx_1.5mm dx_1mm dx_2mm_m_4"
all="$all dx_1.5mm_m_4 m_4 soft_k_field soft_k_field_m_2 soft_k_field_m_4 $compliance dx_0.5mm"
all="$all brittle_dx_0.5mm"
for name in ${CT_RUNS:-$all}; do
  echo "== $name"
  start=$(date +%s)
  mpirun -np 2 "$solver" "results/$name/run.prm" | grep -E '^(Particles|Coupling|Critical|Sequentially)'
  echo "   $(( $(date +%s) - start )) s"
done
# The runs that finished (statistics.csv written), in the order given; some: whether any did
# (a table whose runs did not run is left out, so that CT_RUNS="full_pd coupled schwarz" works).
finished() { for name in "$@"; do [ -f "results/$name/statistics.csv" ] && echo "results/$name"; done; }
some() { [ -n "$(finished "$@")" ]; }
brittle_runs="brittle_dx_2mm_m_2 brittle_dx_1.5mm_m_2 brittle_m_2 brittle_dx_2mm brittle_dx_1.5mm"
brittle_runs="$brittle_runs brittle_full_pd brittle_dx_0.5mm brittle_dx_2mm_m_4 brittle_dx_1.5mm_m_4 brittle_m_4"
soft_runs="dx_2mm dx_1.5mm dx_1mm dx_0.5mm dx_2mm_m_4 dx_1.5mm_m_4 m_4 dx_0.5mm_m_4 dx_0.4mm_m_4"
if some brittle_dx_2mm brittle_full_pd brittle_dx_0.5mm brittle_m_2 brittle_m_4; then
  echo "== brittle bonds: convergence with dx (delta = 3.015 dx) and with m = delta/dx (dx = 1 mm)"
  /usr/bin/python3 postprocess.py $(finished brittle_dx_2mm brittle_full_pd brittle_dx_0.5mm) |
    grep -v "^peak load ratio"
  /usr/bin/python3 postprocess.py $(finished brittle_m_2 brittle_full_pd brittle_m_4) | grep -v "^peak load ratio"
fi
tip=""
if some k_field_m_2 k_field k_field_m_4; then
  echo "== the crack-tip toughness of the lattice (k_field.prm): r = K_tip / K_Ic"
  /usr/bin/python3 k_field.py $(finished k_field_m_2 k_field k_field_m_4)
  tip=$(/usr/bin/python3 k_field.py $(finished k_field_m_2 k_field k_field_m_4) |
    awk -F'|' 'NR > 2 && $6 + 0 > 0 { printf "%s%s=%s", sep, $2 + 0, $6 + 0; sep = "," }')
fi
if some $brittle_runs $soft_runs; then
  echo "== where the peak comes from (measures.py; --tip: r of the table above)"
  /usr/bin/python3 measures.py $(finished $brittle_runs $soft_runs) ${tip:+--tip "$tip"} \
    --plot compact_tension_convergence.png
fi
if some $soft_runs soft_k_field_m_2 soft_k_field soft_k_field_m_4; then
  echo "== softening bonds (n = ${SOFT_RATIO:-2}, N = ${SOFT_TEETH:-8}): the CT peaks and the crack-tip toughness"
  if some $soft_runs; then
    /usr/bin/python3 postprocess.py $(finished $soft_runs) | grep -v "^peak load ratio"
  fi
  if some soft_k_field_m_2 soft_k_field soft_k_field_m_4; then
    /usr/bin/python3 k_field.py $(finished soft_k_field_m_2 soft_k_field soft_k_field_m_4)
  fi
fi
if [ $(finished $compliance | wc -l) = 24 ]; then
  echo "== the LEFM load of the PD specimen itself, from its compliance (compliance.py), and the"
  echo "   softening runs' peaks against it and against ASTM"
  /usr/bin/python3 compliance.py $(finished $compliance) --peaks $(finished $soft_runs) \
    --plot compact_tension_lefm.png
fi
echo "== the FE check of ASTM E399's formula for this specimen and pins (fe_check.py)"
/usr/bin/python3 fe_check.py --dx 1 --h 0.25
echo "== all-PD and coupled (blended, overlapping Schwarz), the shipped law"
/usr/bin/python3 postprocess.py $(finished full_pd coupled schwarz) --plot compact_tension
