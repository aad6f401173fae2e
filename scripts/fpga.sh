#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
#
# Out-of-context place and route of the core on iCE40 FPGAs (rtl/fpga/README.md): Yosys
# synth_ice40, then nextpnr-ice40, of the harnesses in rtl/fpga/ (registered IO around
# specular_unit, specular_stream and specular_axil), and a summary of LUTs, FFs, block RAMs, DSPs, Fmax
# and pixels per second per harness and device. `make fpga` runs it; so does `make report`.
#
#   scripts/fpga.sh [--top unit|stream|axil|phong|all] [--device hx8k|up5k|all] [--out DIR]
#                   [--param NAME=VALUE]... [--seed N] [--freq-hx8k MHZ] [--freq-up5k MHZ]
#                   [--strict] [--fresh] [--elaborate-only]
#
#   --top         the core in the harness fpga_ooc (its parameter Top): unit
#                 (specular_unit), stream (specular_stream), axil (specular_axil: the
#                 AXI4-Lite core), all (default: those three) or phong (phong_stream, the
#                 per-pixel Blinn-Phong competitor of docs/phong_hw.md; its configurations
#                 by --param, roms/phong/phong_configs.cmake)
#   --device      hx8k (iCE40-HX8K, package ct256, LUT multipliers), up5k (iCE40-UP5K,
#                 package sg48, synth_ice40 -dsp: SB_MAC16 multipliers) or all (default)
#   --out         output directory (default build/fpga); one folder per run, TOP_DEVICE/,
#                 and summary.json, summary.md
#   --param       a core parameter by name, e.g. --param CosAddrBits=9
#                 --param CosRomFile=build/roms9/cos_k_1_2_4_16.hex (repeatable; paths
#                 relative to the repository root). Interface widths (CBits, AngleBits,
#                 NBits, LenBits, TagBits, AddrWidth) go to
#                 the harness, every other name to the core
#                 module (chparam before elaboration), so any parameter the core has can be
#                 set and the core's own defaults apply to the rest. Integers and Verilog
#                 literals (40'h...) are passed as numbers, anything else as a string.
#                 FPGA_PARAMS="NAME=VALUE NAME=VALUE" in the environment adds more.
#   --seed        nextpnr placement seed (default 1, or FPGA_SEED)
#   --freq-hx8k, --freq-up5k   nextpnr timing targets in MHz (default 100 and 50)
#   --strict      exit 1 when a run does not fit or misses its frequency target
#   --fresh       re-run even when sources, parameters, ROM files and tools are unchanged
#                 (otherwise an unchanged run's result is reused)
#   --elaborate-only  only elaborate the harnesses in Yosys (hierarchy -check), no synthesis
#
# A design that does not fit (nextpnr "Unable to place ...") is a result, reported as
# fit = no with nextpnr's reason, not an error. Missed timing is a result too (nextpnr runs
# with --timing-allow-fail; the achieved Fmax is reported against the target).
# Exit status: 0 done, 1 a tool failed (or --strict and a run failed to fit or close
# timing), 2 bad arguments.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
me=scripts/fpga.sh

die_usage() {
  echo "$me: $*" >&2
  echo "usage: $me [--top unit|stream|axil|phong|all] [--device hx8k|up5k|all] [--out DIR] [--param NAME=VALUE]... [--seed N] [--freq-hx8k MHZ] [--freq-up5k MHZ] [--strict] [--fresh] [--elaborate-only]" >&2
  exit 2
}

top_arg=all
dev_arg=all
out=build/fpga
seed=${FPGA_SEED:-1}
freq_hx8k=100
freq_up5k=50
strict=0
fresh=0
elab_only=0
params=()
for p in ${FPGA_PARAMS:-}; do params+=("$p"); done

need_value() { [ $# -ge 2 ] || die_usage "$1 needs a value"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --top)       need_value "$@"; top_arg=$2; shift 2 ;;
    --device)    need_value "$@"; dev_arg=$2; shift 2 ;;
    --out)       need_value "$@"; out=$2; shift 2 ;;
    --param)     need_value "$@"; params+=("$2"); shift 2 ;;
    --seed)      need_value "$@"; seed=$2; shift 2 ;;
    --freq-hx8k) need_value "$@"; freq_hx8k=$2; shift 2 ;;
    --freq-up5k) need_value "$@"; freq_up5k=$2; shift 2 ;;
    --strict)    strict=1; shift ;;
    --fresh)     fresh=1; shift ;;
    --elaborate-only) elab_only=1; shift ;;
    -h|--help)   sed -n '4,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *)           die_usage "unknown argument '$1' (allowed: --top, --device, --out, --param, --seed, --freq-hx8k, --freq-up5k, --strict, --fresh, --elaborate-only, --help)" ;;
  esac
done

case "$top_arg" in
  unit|stream|axil|phong) tops=("$top_arg") ;;
  all)         tops=(unit stream axil) ;;
  *) die_usage "--top must be one of unit, stream, axil, phong, all (got '$top_arg')" ;;
esac
case "$dev_arg" in
  hx8k|up5k) devices=("$dev_arg") ;;
  all)       devices=(hx8k up5k) ;;
  *) die_usage "--device must be one of hx8k, up5k, all (got '$dev_arg')" ;;
esac
[[ "$seed" =~ ^[0-9]+$ ]] || die_usage "--seed must be a non-negative integer (got '$seed')"
for f in "$freq_hx8k" "$freq_up5k"; do
  [[ "$f" =~ ^[0-9]+([.][0-9]+)?$ ]] && awk -v f="$f" 'BEGIN { exit !(f > 0) }' ||
    die_usage "--freq-hx8k / --freq-up5k must be a positive number of MHz (got '$f')"
done

# Parameters: NAME=VALUE, NAME an identifier; numbers and sized literals as they are,
# anything else a quoted string (no quotes, backslashes or spaces inside).
harness_widths=" CBits AngleBits NBits LenBits TagBits AddrWidth VecBits "
core_chparam=()
harness_chparam=()
for p in "${params[@]+"${params[@]}"}"; do
  [[ "$p" == *=* ]] || die_usage "--param must be NAME=VALUE (got '$p')"
  name=${p%%=*}
  value=${p#*=}
  [[ "$name" =~ ^[A-Za-z_][A-Za-z0-9_]*$ ]] || die_usage "--param name must be a Verilog identifier (got '$name')"
  [ -n "$value" ] || die_usage "--param $name has an empty value"
  if [[ "$value" =~ ^-?[0-9]+$ ]] || [[ "$value" =~ ^[0-9]*\'[sS]?[bBoOdDhH][0-9a-fA-F_xXzZ]+$ ]]; then
    arg="-set $name $value"
  elif [[ "$value" =~ ^[^\"\\[:space:]]+$ ]]; then
    arg="-set $name \"$value\""
  else
    die_usage "--param $name: a string value must not contain quotes, backslashes or spaces (got '$value')"
  fi
  if [[ "$harness_widths" == *" $name "* ]]; then harness_chparam+=("$arg"); else core_chparam+=("$arg"); fi
done

for tool in yosys nextpnr-ice40 python3; do
  command -v "$tool" > /dev/null || { echo "$me: $tool is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
done

cd "$root"
mkdir -p "$out"
out=$(cd "$out" && pwd)
# The core's sources in compile order and its include directories (rtl/specular.f,
# rtl/README.md), then the harnesses.
# shellcheck source=scripts/rtl_filelist.sh
source scripts/rtl_filelist.sh
rtl_filelist || exit 1
sources=("${RTL_SOURCES[@]}")
incflags=""
for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do incflags+=" -I$d"; done
sources+=(rtl/fpga/fpga_ooc_io.sv rtl/fpga/fpga_ooc.sv)

harness=fpga_ooc
# fpga_ooc's parameter Top for each --top (rtl/fpga/fpga_ooc.sv).
top_id_of()  { case "$1" in unit) echo 0 ;; stream) echo 1 ;; axil) echo 2 ;; phong) echo 3 ;; esac; }
core_of()    { case "$1" in unit) echo specular_unit ;; stream) echo specular_stream ;; axil) echo specular_axil ;;
                            phong) echo phong_stream ;; esac; }

# Everything a run's result depends on: sources, ROM files (the defaults in roms/ and any
# file named by a parameter), parameters, options, this script and the tool versions.
run_key() {
  {
    printf '%s\n' "$@" "${params[@]+"${params[@]}"}"
    for f in "${sources[@]}" rtl/specular.f "$me"; do sha256sum "$f"; done
    for d in "${RTL_INCDIRS[@]+"${RTL_INCDIRS[@]}"}"; do
      find "$d" -maxdepth 1 -name '*.svh' -type f -print0 | sort -z | xargs -0 -r sha256sum
    done
    find roms -name '*.hex' -type f -print0 2>/dev/null | sort -z | xargs -0 -r sha256sum
    for p in "${params[@]+"${params[@]}"}"; do [ -f "${p#*=}" ] && sha256sum "${p#*=}"; done
    yosys -V; nextpnr-ice40 --version 2>&1
  } 2>/dev/null | sha256sum | cut -d' ' -f1
}

failed=0
run_dirs=()
for top in "${tops[@]}"; do
  top_id=$(top_id_of "$top")
  core=$(core_of "$top")
  for dev in "${devices[@]}"; do
    dir="$out/${top}_${dev}"
    mkdir -p "$dir"
    case "$dev" in
      hx8k) pnr_dev="--hx8k --package ct256"; freq=$freq_hx8k; dsp="" ;;
      up5k) pnr_dev="--up5k --package sg48";  freq=$freq_up5k; dsp=" -dsp" ;;
    esac
    {
      echo "read_verilog -sv -defer${incflags} ${sources[*]}"
      for a in "${core_chparam[@]+"${core_chparam[@]}"}"; do echo "chparam $a $core"; done
      echo "chparam -set Top $top_id $harness"
      for a in "${harness_chparam[@]+"${harness_chparam[@]}"}"; do echo "chparam $a $harness"; done
      echo "hierarchy -check -top $harness"
      if [ "$elab_only" = 1 ]; then
        echo "proc"
        echo "check -assert"
      else
        echo "synth_ice40 -top $harness$dsp -json $dir/$harness.json"
        echo "tee -q -o $dir/stat.txt stat"
      fi
    } > "$dir/synth.ys"

    if [ "$elab_only" = 1 ]; then
      if yosys -q -l "$dir/elaborate.log" -s "$dir/synth.ys" > /dev/null 2>&1; then
        echo "$me: $harness ($top) elaborates (Yosys hierarchy -check, proc, check -assert)"
      else
        echo "$me: $harness ($top) does not elaborate; last lines of $dir/elaborate.log:" >&2
        tail -n 15 "$dir/elaborate.log" >&2
        failed=1
      fi
      continue
    fi

    key=$(run_key "$top" "$dev" "$freq" "$seed")
    if [ "$fresh" = 0 ] && [ -f "$dir/result.json" ] && [ "$(cat "$dir/key" 2>/dev/null)" = "$key" ]; then
      echo "$me: $top on $dev unchanged since the last run, result reused ($dir)"
      run_dirs+=("$dir")
      continue
    fi
    rm -f "$dir/result.json" "$dir/key" "$dir/report.json" "$dir/stat.txt"

    echo "$me: $top on $dev: Yosys synth_ice40$dsp ..."
    t0=$(date +%s)
    synth_rc=0
    yosys -q -l "$dir/yosys.log" -s "$dir/synth.ys" > /dev/null 2>&1 || synth_rc=$?
    pnr_rc=-1
    if [ "$synth_rc" = 0 ]; then
      echo "$me: $top on $dev: nextpnr-ice40 $pnr_dev --freq $freq --seed $seed ..."
      pnr_rc=0
      # shellcheck disable=SC2086
      nextpnr-ice40 $pnr_dev --json "$dir/$harness.json" --freq "$freq" --seed "$seed" \
        --pcf-allow-unconstrained --timing-allow-fail --report "$dir/report.json" \
        -l "$dir/nextpnr.log" -q > /dev/null 2>&1 || pnr_rc=$?
    else
      echo "$me: Yosys failed on $top ($dir/yosys.log):" >&2
      tail -n 15 "$dir/yosys.log" >&2
    fi
    t1=$(date +%s)
    python3 - "$dir" "$top" "$dev" "$harness" "$core" "$freq" "$seed" "$synth_rc" "$pnr_rc" \
      "$((t1 - t0))" "${params[@]+"${params[@]}"}" <<'PY'
import json, os, re, sys
d, top, dev, harness, core, freq, seed, synth_rc, pnr_rc, secs = sys.argv[1:11]
params = sys.argv[11:]
res = {"top": top, "harness": harness, "core": core, "device": dev,
       "part": {"hx8k": "iCE40-HX8K ct256", "up5k": "iCE40-UP5K sg48"}[dev],
       "dsp_mapping": dev == "up5k", "target_mhz": float(freq), "seed": int(seed),
       "params": params, "seconds": int(secs), "dir": d}

def read(p):
    try:
        return open(p, errors="replace").read()
    except OSError:
        return ""

cells = {}
for line in read(os.path.join(d, "stat.txt")).splitlines():
    m = re.match(r"\s+(SB_\w+|\$\S+)\s+(\d+)\s*$", line)
    if m:
        cells[m[1]] = cells.get(m[1], 0) + int(m[2])
res["yosys"] = {"lut4": cells.get("SB_LUT4", 0),
                "ff": sum(v for k, v in cells.items() if k.startswith("SB_DFF")),
                "carry": cells.get("SB_CARRY", 0),
                "bram": cells.get("SB_RAM40_4K", 0),
                "dsp": cells.get("SB_MAC16", 0)}
log = read(os.path.join(d, "nextpnr.log"))
if int(synth_rc) != 0:
    res["status"] = "synthesis failed"
    res["fit"] = None
    res["reason"] = "Yosys failed, see yosys.log"
else:
    nofit = re.search(r"(Unable to place[^\n]*|[^\n]*no BELs remaining[^\n]*|[^\n]*[Dd]esign (is )?too (large|big)[^\n]*)", log)
    rep = {}
    try:
        rep = json.load(open(os.path.join(d, "report.json")))
    except (OSError, ValueError):
        pass
    if nofit:
        res["status"] = "does not fit"
        res["fit"] = False
        res["reason"] = re.sub(r"^(ERROR|Info): ", "", nofit[0].strip())
    elif int(pnr_rc) != 0 or not rep:
        res["status"] = "nextpnr failed"
        res["fit"] = None
        errs = [l for l in log.splitlines() if "ERROR" in l]
        res["reason"] = (errs[-1] if errs else f"exit {pnr_rc}") + " (see nextpnr.log)"
    else:
        res["status"] = "placed and routed"
        res["fit"] = True
    util = rep.get("utilization", {})
    def used(k):
        return util.get(k, {}).get("used")
    def avail(k):
        return util.get(k, {}).get("available")
    res["nextpnr"] = {k: {"used": used(k), "available": avail(k)}
                      for k in ("ICESTORM_LC", "ICESTORM_RAM", "ICESTORM_DSP", "SB_IO", "SB_GB") if k in util}
    # the core clock is the harness's clk_i (the only clock)
    fmax = rep.get("fmax", {})
    clk = next((k for k in fmax if "clk_i" in k), next(iter(fmax), None))
    if clk is not None and res["fit"]:
        res["clock"] = clk
        res["fmax_mhz"] = round(float(fmax[clk]["achieved"]), 2)
        res["timing_met"] = res["fmax_mhz"] >= float(freq)
        res["pixels_per_second"] = res["fmax_mhz"] * 1e6  # one pixel per clock
    elif res["fit"]:
        m = re.findall(r"Max frequency for clock +'([^']*)': ([0-9.]+) MHz", log)
        if m:
            res["clock"], f = m[-1]
            res["fmax_mhz"] = float(f)
            res["timing_met"] = res["fmax_mhz"] >= float(freq)
            res["pixels_per_second"] = res["fmax_mhz"] * 1e6
    # critical path: first and last cell, the nets and delays
    for cp in rep.get("critical_paths", []):
        if clk is None or not cp.get("from", "").endswith(" " + clk) or not cp.get("to", "").endswith(" " + clk):
            continue
        steps = cp.get("path", [])
        if not steps:
            continue
        nets = [s.get("net") for s in steps if s.get("type") == "routing" and s.get("net")]
        logic = [s for s in steps if s.get("type") == "logic"]
        res["critical_path"] = {
            "from_cell": steps[0].get("from", {}).get("cell"),
            "to_cell": steps[-1].get("to", {}).get("cell"),
            "from_net": nets[0] if nets else None,
            "to_net": nets[-1] if nets else None,
            "logic_levels": len(logic),
            "logic_ns": round(sum(s.get("delay", 0) for s in logic), 2),
            "routing_ns": round(sum(s.get("delay", 0) for s in steps if s.get("type") == "routing"), 2),
            "total_ns": round(sum(s.get("delay", 0) for s in steps), 2),
            # the hierarchy the path crosses, in order (net names less their last component)
            "through": list(dict.fromkeys(x.rsplit(".", 1)[0] for x in nets if "." in x)),
            "nets": nets}
        break
res["luts"] = (res.get("nextpnr", {}).get("ICESTORM_LC", {}) or {}).get("used") if res["fit"] else None
json.dump(res, open(os.path.join(d, "result.json"), "w"), indent=1)
PY
    st=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["status"])' "$dir/result.json")
    if [ "$st" = "placed and routed" ] || [ "$st" = "does not fit" ]; then
      echo "$key" > "$dir/key"
    else
      failed=1
    fi
    echo "$me: $top on $dev: $st ($((t1 - t0)) s)"
    run_dirs+=("$dir")
  done
done

[ "$elab_only" = 1 ] && exit "$failed"

rc=0
python3 - "$out" "$strict" "${run_dirs[@]}" <<'PY' || rc=$?
import json, os, sys
out, strict, dirs = sys.argv[1], sys.argv[2] == "1", sys.argv[3:]
runs = [json.load(open(os.path.join(d, "result.json"))) for d in dirs]
json.dump({"runs": runs}, open(os.path.join(out, "summary.json"), "w"), indent=1)

def n(v):
    return "-" if v is None else str(v)

rows = ["| core | device | fit | LCs (ICESTORM_LC) | SB_LUT4 | FFs | BRAMs | DSPs | Fmax (MHz) | target (MHz) | pixels per second |",
        "|---|---|---|---|---|---|---|---|---|---|---|"]
notes = []
for r in runs:
    y = r["yosys"]
    npr = r.get("nextpnr", {})
    fit = {True: "yes", False: "no", None: "error"}[r["fit"]]
    if r["fit"]:
        bram = npr.get("ICESTORM_RAM", {}).get("used", y["bram"])
        dsp = npr.get("ICESTORM_DSP", {}).get("used", y["dsp"])
    else:
        bram, dsp = y["bram"], y["dsp"]
    lc = r.get("luts")
    lcs = f"{lc} / {npr['ICESTORM_LC']['available']}" if lc is not None and "ICESTORM_LC" in npr else "-"
    fmax = r.get("fmax_mhz")
    f = "-" if fmax is None else f"{fmax:.2f}" + ("" if r.get("timing_met") else " (missed)")
    pps = "-" if fmax is None else f"{fmax * 1e6:.3g}"
    rows.append(f"| {r['core']} | {r['part']} | {fit} | {lcs} | {y['lut4']} | {y['ff']} | {bram} | {dsp} | {f} | {r['target_mhz']:g} | {pps} |")
    if r["fit"] is not True:
        notes.append(f"- {r['core']} on {r['part']}: {r['status']}: {r.get('reason', '')}")
    cp = r.get("critical_path")
    if cp:
        notes.append(f"- {r['core']} on {r['part']}: critical path {cp['total_ns']} ns ({cp['logic_levels']} logic cells, "
                     f"{cp['logic_ns']} ns logic, {cp['routing_ns']} ns routing) from net `{cp['from_net']}` to net `{cp['to_net']}` "
                     f"(through {', '.join(cp['through']) or '-'}; cells in result.json)")
params = sorted({p for r in runs for p in r["params"]})
md = ["# Out-of-context place and route (scripts/fpga.sh)", "",
      "Harnesses rtl/fpga/ (registered IO), Yosys `synth_ice40` (`-dsp` on the UP5K), nextpnr-ice40 with the "
      "seed and frequency target shown; LCs are logic cells used after packing (a LUT4 and/or a flip-flop each); "
      "SB_LUT4 and FFs are Yosys' cell counts (harness included); pixels per second = Fmax at one pixel per clock.",
      "", "Parameter overrides: " + (", ".join(f"`{p}`" for p in params) if params else "none (the core's defaults)"), ""]
md += rows + [""] + notes
open(os.path.join(out, "summary.md"), "w").write("\n".join(md) + "\n")
print("\n".join(rows + [""] + notes))
print(f"\nwrote {os.path.join(out, 'summary.json')} and summary.md")
bad = [r for r in runs if r["fit"] is None]
if strict:
    bad += [r for r in runs if r["fit"] is False or (r["fit"] and not r.get("timing_met"))]
sys.exit(1 if bad else 0)
PY
[ "$failed" = 0 ] || exit 1
exit "$rc"
