#!/usr/bin/env bash
# SLAM accuracy on drives from `slamroute drive` in the default city (bench/RESULTS.md,
# "Odometry: accuracy on drives from `slamroute drive`"). Usage: bench/odometry_drives.sh [BUILD_DIR] [OUT_DIR]
#   route1k: 1.2 km through building-lined and open streets; loop: one block, back to its start;
#   city: the three 7 km routes of `slamroute run` (out/default_city/routes, if it exists).
# Drives record wheel odometry + gyro + IMU roll/pitch (odometry.csv); "lidar_only" rows ignore it.
# Prints one Markdown row per evaluation. Takes ~15 min on 2 cores (~45 min with the city).
source "$(dirname "$0")/script_help.sh" && exit_on_help "$0" "$@"
# Braced and ended by exit: bash parses the whole script before it runs, so an edit or a
# git pull during a long sweep does not change the sweep that is running.
{
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../build}"
out="${2:-/tmp/slamroute_odometry_bench}"
bin="$build/cli/slamroute"
mkdir -p "$out"
# Noise-free: LiDAR and wheel odometry + gyro without noise.
printf 'simulate:\n  lidar:\n    range_sigma_m: 0.0\n    dropout_prob: 0.0\n  drive:\n    odometry_scale_sigma: 0.0\n    odometry_speed_noise_mps: 0.0\n    gyro_bias_sigma_deg_s: 0.0\n    gyro_noise_deg_s: 0.0\n    tilt_bias_sigma_deg: 0.0\n    tilt_noise_deg: 0.0\n' > "$out/noisefree.yaml"
printf 'evaluate:\n  odometry:\n    use_wheel_odometry: false\n' > "$out/lidar_only.yaml"
printf 'evaluate:\n  loop:\n    enabled: false\n' > "$out/nolc.yaml"
printf 'evaluate:\n  loop:\n    enabled: false\n  odometry:\n    use_wheel_odometry: false\n' > "$out/nolc_lidar_only.yaml"

drive() {  # name route [extra args]
  local name=$1 route=$2; shift 2
  [ -f "$out/$name/groundtruth.tum" ] || "$bin" --log-level warn "$@" drive --route "$route" --out "$out/$name"
}
evaluate() {  # drive eval [global args] (e.g. --config F)
  local d=$1 e=$2; shift 2
  "$bin" --log-level warn "$@" evaluate --drive "$out/$d" --out "$out/$e" > /dev/null
  python3 - "$out/$e/metrics.json" "$e" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
f = lambda k, p=3: ("%.*f" % (p, j[k])) if isinstance(j.get(k), (int, float)) else "–"
print(f"| {sys.argv[2]} | {j['evaluated_length_m']/1000:.2f} | {f('ate_rmse_m')} | {f('ate_max_m',2)} | "
      f"{f('rpe_trans_pct',2)} | {f('rpe_segment_trans_pct',2)} | {j['loop_closures']} | "
      f"{f('map_mean_dist_m',2)} / {f('map_p95_dist_m',2)} | {j['reliability']['unreliable_scans']} | "
      f"{j['scans']} | {f('scans_per_s',1)} | " +
      " / ".join("%.2f" % j["drift_by_label"][k]["drift_pct"] if k in j.get("drift_by_label", {}) else "–"
                 for k in ("rich", "wall", "open")) + " |")
PY
}

echo "| evaluation | km | ATE RMSE [m] | ATE max [m] | RPE 100-800 m [%] | RPE 50 m [%] | loop closures | map error mean / p95 [m] | unreliable scans | scans used | scans/s (1 core) | drift rich / wall / open streets [%] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
drive drive1k_clean "$here/routes/route1k.json" --config "$out/noisefree.yaml"
drive drive1k_noisy "$here/routes/route1k.json"
drive loop_noisy "$here/routes/loop.json"
evaluate drive1k_clean route1k_noisefree
evaluate drive1k_clean route1k_noisefree_lidar_only --config "$out/lidar_only.yaml"
evaluate drive1k_noisy route1k_noisy_no_loop_closure --config "$out/nolc.yaml"
evaluate drive1k_noisy route1k_noisy_lidar_only_no_loop_closure --config "$out/nolc_lidar_only.yaml"
evaluate loop_noisy loop_noisy_no_loop_closure --config "$out/nolc.yaml"
evaluate loop_noisy loop_noisy
city="$here/../out/default_city/routes"
if [ -d "$city" ] && [ "${SKIP_CITY:-0}" != 1 ]; then
  for p in qlearning random postman; do
    drive "city_$p" "$city/$p.json"
    evaluate "city_$p" "city_${p}"
    evaluate "city_$p" "city_${p}_no_loop_closure" --config "$out/nolc.yaml"
  done
fi
exit
}
