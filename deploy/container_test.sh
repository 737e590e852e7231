#!/usr/bin/env bash
# The container stage: builds deploy/Dockerfile with podman and proves the image serves.
#   1. makes the debian:bookworm and debian:bookworm-slim base images if podman lacks them
#      (debootstrap from this machine's apt mirror: no registry is reachable here);
#   2. builds deploy/Dockerfile (docker format, so the HEALTHCHECK is kept);
#   3. runs it as Kubernetes would (read-only root, no capabilities, no new privileges), waits for
#      /readyz, checks /healthz, /metrics and the image's HEALTHCHECK, streams to 100
#      ocean-loadtest clients over UDP through the published port (--udp-public-port: no client
#      may fall back to TCP; >= 99 % on time) and 5 over TCP (every frame checked
#      against the sim: 0 bad frames), then SIGTERM must stop it with exit status 0 within 5 s;
#   4. `podman kube play` of manifests derived from deploy/k8s (the timeline's etcd as a Pod, then
#      ConfigMap, Secret, Deployment with 3 replicas following it): the 3 pods must send
#      byte-identical frames for the same tick, decoding to the same sea, across an admin change
#      made through one of them (tests/replica's hidden [external] case), and each must have
#      applied it; then a load test given two pods (--server A,B) while one pod is removed:
#      every client must fail over and keep receiving good frames.
# Usage: deploy/container_test.sh [--no-kube]
# Needs the host's ocean-loadtest and test_replica ($OCEAN_BUILD_DIR, default build/;
# ./deploy/build.sh makes them)
# and podman, runc, catatonit and debootstrap (OCEAN_CONTAINER=1 ./deploy/install-deps.sh).
# Exit status: 0 passed; 1 failed (the reason is the last line); 77 skipped because podman cannot
# create any container on this machine (the probe's error is printed).
set -euo pipefail
cd "$(dirname "$0")/.."

kube=1
for arg in "$@"; do
  case "$arg" in
    --no-kube) kube=0 ;;
    *) echo "usage: deploy/container_test.sh [--no-kube]" >&2; exit 2 ;;
  esac
done

image=ocean-server:0.1.0          # the tag deploy/k8s/kustomization.yaml names
build_dir=${OCEAN_BUILD_DIR:-build}
loadtest=$build_dir/client/loadtest/ocean-loadtest
replica_test=$build_dir/tests/replica/test_replica
admin=$build_dir/tools/admin/ocean-admin
replicas=3
stage_start=$SECONDS
name=ocean-ct-$$
work=$(mktemp -d)

say() { echo "container_test: $*" >&2; }
fail() {
  say "FAILED: $*"
  exit 1
}

# The facts of this machine (DESIGN.md section 6): runc, cgroupfs, no default ulimits.
if [[ -z "${CONTAINERS_CONF:-}" ]]; then
  printf '[containers]\ndefault_ulimits = []\n' > "$work/containers.conf"
  export CONTAINERS_CONF=$work/containers.conf
fi
podman_args=(--runtime runc --cgroup-manager=cgroupfs)
pm() { podman "${podman_args[@]}" "$@"; }

kube_file=
timeline_file=
cleanup() {
  pm rm -f -t 0 "$name" >/dev/null 2>&1 || true
  if [[ -n "$timeline_file" ]]; then
    pm kube down "$timeline_file" >/dev/null 2>&1 || true
    pm pod rm -f -t 0 "$name-timeline" >/dev/null 2>&1 || true
  fi
  if [[ -n "$kube_file" ]]; then
    pm kube down "$kube_file" >/dev/null 2>&1 || true
    # One at a time: podman removes none of a list that names a pod already gone.
    for ((i = 0; i < replicas; ++i)); do
      pod=$name-pod-$i
      pm pod rm -f -t 0 "$pod" >/dev/null 2>&1 || true
    done
    pm secret rm "$name-secrets" >/dev/null 2>&1 || true
    pm volume rm -f "$name-secrets" "$name-config" >/dev/null 2>&1 || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT

for tool in podman runc catatonit debootstrap curl python3; do
  command -v "$tool" >/dev/null ||
    fail "$tool is not installed: run OCEAN_CONTAINER=1 ./deploy/install-deps.sh"
done
[[ -x "$loadtest" ]] || fail "$loadtest is missing: run ./deploy/build.sh first"
((kube == 0)) || [[ -x "$replica_test" ]] || fail "$replica_test is missing: run ./deploy/build.sh first"
((kube == 0)) || [[ -x "$admin" ]] || fail "$admin is missing: run ./deploy/build.sh first"
((kube == 0)) || [[ -x /usr/bin/etcd ]] || fail "/usr/bin/etcd is missing: run ./deploy/install-deps.sh (etcd-server)"

# --- Can podman create a container here at all? -------------------------------------------------
# The probe runs the host's /bin/true from a throw-away rootfs, so neither a base image nor the
# network is involved: if this fails, the kernel or the privileges deny containers (no user or
# network namespaces, no cgroups, no overlay, ...), and that is the one reason to skip.
probe=$work/probe
mkdir -p "$probe/bin"
cp /bin/true "$probe/bin/true"
for lib in $(ldd /bin/true | grep -o '/[^ ]*'); do
  mkdir -p "$probe$(dirname "$lib")"
  cp -L "$lib" "$probe$lib"
done
if ! probe_out=$(pm run --rm --rootfs "$probe" /bin/true 2>&1); then
  say "SKIPPED: podman cannot run a container on this machine (probe: podman run --rootfs with /bin/true):"
  echo "$probe_out" >&2
  exit 77
fi

# --- Base images, made locally (cached in podman's storage) --------------------------------------
debian_mirror() {
  local uri
  uri=$(awk '/^URIs:/ {u=$2} /^Suites:/ && / bookworm( |$)/ {print u; exit}' /etc/apt/sources.list.d/*.sources 2>/dev/null || true)
  [[ -n "$uri" ]] || uri=$(awk '$1=="deb" && $3=="bookworm" {print $2; exit}' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null || true)
  echo "${OCEAN_DEBIAN_MIRROR:-${uri:-http://deb.debian.org/debian}}"
}
if ! pm image exists debian:bookworm || ! pm image exists debian:bookworm-slim; then
  mirror=$(debian_mirror)
  say "making debian:bookworm and debian:bookworm-slim with debootstrap from $mirror"
  t0=$SECONDS
  nice debootstrap --variant=minbase bookworm "$work/rootfs" "$mirror" > "$work/debootstrap.log" 2>&1 ||
    { tail -20 "$work/debootstrap.log" >&2; fail "debootstrap of bookworm from $mirror failed"; }
  path='ENV PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin'
  # As Debian's own images: no package cache or package lists (apt-get update fetches them).
  tar -C "$work/rootfs" -c --exclude='./var/cache/apt/archives/*.deb' --exclude='./var/lib/apt/lists/*' . |
    pm import --quiet --change "$path" - debian:bookworm >/dev/null
  # slim as Debian's own: no documentation, manuals or translations, now or from later installs.
  mkdir -p "$work/rootfs/etc/dpkg/dpkg.cfg.d"
  printf 'path-exclude /usr/share/doc/*\npath-include /usr/share/doc/*/copyright\npath-exclude /usr/share/man/*\npath-exclude /usr/share/info/*\npath-exclude /usr/share/locale/*\n' \
    > "$work/rootfs/etc/dpkg/dpkg.cfg.d/slim"
  find "$work/rootfs/usr/share/doc" -type f ! -name copyright -delete
  tar -C "$work/rootfs" -c --exclude='./var/cache/apt/archives/*.deb' --exclude='./var/lib/apt/lists/*' \
    --exclude='./usr/share/man/*' \
    --exclude='./usr/share/info/*' --exclude='./usr/share/locale/*' . |
    pm import --quiet --change "$path" - debian:bookworm-slim >/dev/null
  rm -rf "$work/rootfs"
  say "base images made in $((SECONDS - t0)) s"
fi

# --- Build ---------------------------------------------------------------------------------------
# podman 4.3 reads only <context>/.dockerignore by itself; the ignore file keeps build trees out.
say "building $image from deploy/Dockerfile"
t0=$SECONDS
nice podman "${podman_args[@]}" build --format docker --ignorefile deploy/Dockerfile.dockerignore -f deploy/Dockerfile \
  -t "$image" . > "$work/build.log" 2>&1 || { tail -40 "$work/build.log" >&2; fail "podman build of deploy/Dockerfile failed"; }
build_s=$((SECONDS - t0))
size=$(pm image inspect --format '{{.Size}}' "$image")
user=$(pm image inspect --format '{{.Config.User}}' "$image")
cached=$(grep -c '^--> Using cache' "$work/build.log" || true)
say "built in $build_s s ($cached steps from cache), image $((size / 1000000)) MB, user $user"
[[ "$user" == 10001:10001 ]] || fail "the image runs as '$user', not the non-root 10001:10001 the Deployment expects"
# Layers of earlier builds (the compile stage is 1 GB) would pile up run after run.
pm image prune -f >/dev/null 2>&1 || true

free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }

# wait_ready URL CONTAINER: up to 30 s for a 200, failing early if the container has exited.
wait_ready() {
  local url=$1 ctr=$2
  for _ in $(seq 1 150); do
    curl -fsS -o /dev/null --max-time 1 "$url" 2>/dev/null && return 0
    if [[ "$(pm inspect --format '{{.State.Running}}' "$ctr" 2>/dev/null)" != true ]]; then
      pm logs "$ctr" 2>&1 | tail -20 >&2
      fail "container $ctr exited before $url answered"
    fi
    sleep 0.2
  done
  pm logs "$ctr" 2>&1 | tail -20 >&2
  fail "$url did not answer 200 within 30 s"
}

# check_load JSON_FILE WHAT CLIENTS [MIN_RECONNECTS [MIN_ON_TIME_PCT]]: all welcomed, frames
# received, none bad.
check_load() {
  python3 - "$@" <<'EOF'
import json, sys
path, what, clients = sys.argv[1], sys.argv[2], int(sys.argv[3])
min_reconnects = int(sys.argv[4]) if len(sys.argv) > 4 else 0
min_on_time = float(sys.argv[5]) if len(sys.argv) > 5 else 0.0
lines = [l for l in open(path).read().splitlines() if l.startswith("{")]
if not lines:
    sys.exit(f"{what}: ocean-loadtest printed no JSON summary")
s = json.loads(lines[-1])
print(f"container_test: {what}: {s['clients_welcomed']}/{clients} clients welcomed, {s['clients_connected']} connected at the end, "
      f"{s['frames_received']} frames, {s['frames_bad']} bad, {s['frames_ok_pct']}% on time, {s['reconnects']} reconnects", file=sys.stderr)
problems = []
if s["clients_welcomed"] < clients: problems.append(f"only {s['clients_welcomed']} of {clients} clients were welcomed")
if s["clients_connected"] < clients: problems.append(f"only {s['clients_connected']} of {clients} clients were connected at the end")
if s["frames_received"] < clients * 10: problems.append(f"only {s['frames_received']} frames received")
if s["frames_bad"] != 0: problems.append(f"{s['frames_bad']} frames did not match the simulation")
if s["transport"] == "udp" and s["transport_fallbacks"] > 0:
    problems.append(f"{s['transport_fallbacks']} clients fell back to TCP: UDP did not reach the server")
if s["frames_ok_pct"] < min_on_time: problems.append(f"{s['frames_ok_pct']}% of frames on time, expected at least {min_on_time}%")
if s["reconnects"] < min_reconnects: problems.append(f"{s['reconnects']} reconnects, expected at least {min_reconnects} (failover)")
if problems:
    sys.exit(f"{what}: " + "; ".join(problems))
EOF
}

# run_load JSON_FILE ARGS...: ocean-loadtest with --json; its stderr goes to JSON_FILE.err.
run_load() {
  local out=$1
  shift
  local rc=0
  "$loadtest" --json --quiet "$@" > "$out" 2> "$out.err" || rc=$?
  ((rc == 0)) || { cat "$out.err" >&2; fail "ocean-loadtest $* exited with status $rc"; }
}

# --- One container ------------------------------------------------------------------------------
port=$(free_port)
mport=$(free_port)
say "running $image as $name (ports 127.0.0.1:$port tcp+udp, metrics 127.0.0.1:$mport)"
pm run -d --name "$name" --read-only --cap-drop=ALL --security-opt no-new-privileges \
  -p "127.0.0.1:$port:7700/tcp" -p "127.0.0.1:$port:7700/udp" -p "127.0.0.1:$mport:9464/tcp" \
  "$image" --max-clients 200 --max-connections-per-ip 0 --connect-rate-per-ip 0 --udp-public-port "$port" > /dev/null 2> "$work/run.log" || { cat "$work/run.log" >&2; fail "podman run of $image failed"; }
t0=$SECONDS
wait_ready "http://127.0.0.1:$mport/readyz" "$name"
say "/readyz answered 200 after $((SECONDS - t0)) s"
curl -fsS -o /dev/null --max-time 2 "http://127.0.0.1:$mport/healthz" || fail "/healthz did not answer 200"
curl -fsS --max-time 5 "http://127.0.0.1:$mport/metrics" > "$work/metrics" || fail "/metrics did not answer 200"
grep -q '^ocean_build_info{' "$work/metrics" || fail "/metrics has no ocean_build_info series"
pm healthcheck run "$name" > /dev/null 2>&1 || fail "the image's HEALTHCHECK reports the server unhealthy"
[[ "$(pm exec "$name" id -u)" == 10001 ]] || fail "the server process does not run as uid 10001"

run_load "$work/udp.json" --server "127.0.0.1:$port" --clients 100 --ramp 2 --duration 10 --transport udp
check_load "$work/udp.json" "100 UDP clients" 100 0 99 || fail "the load test over UDP did not pass (above)"
run_load "$work/tcp.json" --server "127.0.0.1:$port" --clients 5 --duration 5 --transport tcp
check_load "$work/tcp.json" "5 TCP clients" 5 || fail "the load test over TCP did not pass (above)"

t0=$(date +%s.%N)
pm kill --signal TERM "$name" > /dev/null 2>> "$work/run.log"
status=$(timeout 10 podman "${podman_args[@]}" wait "$name") ||
  fail "the server did not stop within 10 s of SIGTERM"
stop_s=$(python3 -c "import time; print(round(time.time() - $t0, 2))")
[[ "$status" == 0 ]] || { pm logs "$name" 2>&1 | tail -10 >&2; fail "SIGTERM: the server exited with status $status, not 0"; }
python3 -c "import sys; sys.exit(0 if $stop_s < 5 else 1)" || fail "SIGTERM: the server took $stop_s s to stop (limit 5 s)"
# Into a file first: with pipefail, grep -q quitting early makes podman logs die of SIGPIPE.
pm logs "$name" > "$work/server.log" 2>&1
grep -q 'SIGTERM received' "$work/server.log" || fail "SIGTERM: the server's log does not show the signal"
say "SIGTERM: exit status 0 after $stop_s s"
pm rm -f "$name" > /dev/null 2>> "$work/run.log"

if ((kube == 0)); then
  say "passed (kube play skipped: --no-kube) in $((SECONDS - stage_start)) s"
  exit 0
fi

# --- podman kube play: the timeline's store, 3 replicas following it, a change, failover ----------------------------
# The store first (deploy/k8s/timeline-etcd.yaml's StatefulSet as one Pod: podman 4.3 plays no
# StatefulSet). No registry is reachable here, so the pod runs the host's etcd (etcd-server, a
# static binary) in the slim base image, as root on an emptyDir (podman ignores fsGroup).
timeline_file=$work/timeline.yaml
python3 - deploy/k8s "$timeline_file" "$name" <<'EOF'
import sys, yaml
k8s, out, name = sys.argv[1], sys.argv[2], sys.argv[3]
statefulset = next(d for d in yaml.safe_load_all(open(f"{k8s}/timeline-etcd.yaml")) if d["kind"] == "StatefulSet")
pod = statefulset["spec"]["template"]["spec"]
container = pod["containers"][0]
container["image"] = "localhost/debian:bookworm-slim"
peer = "http://127.0.0.1:2380"
container["command"] = ["/usr/local/bin/etcd", "--name=timeline", "--data-dir=/var/lib/etcd/data",
                        "--listen-client-urls=http://0.0.0.0:2379", "--advertise-client-urls=http://127.0.0.1:2379",
                        "--listen-peer-urls=" + peer, "--initial-advertise-peer-urls=" + peer,
                        "--initial-cluster=timeline=" + peer]
del container["ports"]
for probe in ("livenessProbe", "readinessProbe"):
    container[probe]["httpGet"]["port"] = 2379
for key in ("runAsNonRoot", "runAsUser", "runAsGroup", "fsGroup"):
    pod["securityContext"].pop(key, None)
container["securityContext"].pop("runAsNonRoot", None)
container["volumeMounts"].append({"name": "etcd-binary", "mountPath": "/usr/local/bin/etcd", "readOnly": True})
pod["volumes"] = [{"name": "data", "emptyDir": {}},
                  {"name": "etcd-binary", "hostPath": {"path": "/usr/bin/etcd", "type": "File"}}]
labels = statefulset["spec"]["template"]["metadata"]["labels"]
yaml.safe_dump({"apiVersion": "v1", "kind": "Pod", "metadata": {"name": f"{name}-timeline", "labels": labels},
                "spec": pod}, open(out, "w"), sort_keys=False)
EOF
pm kube play "$timeline_file" > "$work/timeline.log" 2>&1 || { cat "$work/timeline.log" >&2; fail "podman kube play of the timeline's store failed"; }
infra=$(pm pod inspect --format '{{.InfraContainerID}}' "$name-timeline") || fail "podman kube play made no pod $name-timeline"
store_ip=$(pm inspect --format "{{range .NetworkSettings.Networks}}{{.IPAddress}} {{end}}" "$infra" | awk "{print \$1}")
[[ -n "$store_ip" ]] || fail "the timeline's pod has no IP address"
wait_ready "http://$store_ip:2379/health" "$name-timeline-etcd"
say "kube play: the timeline's store (etcd) ready at $store_ip:2379"

# Derived from deploy/k8s, changed only where podman 4.3 differs from Kubernetes (each named):
kube_file=$work/fleet.yaml
python3 - deploy/k8s "$kube_file" "$name" "$replicas" "$store_ip" <<'EOF'
import secrets, sys, yaml
k8s, out, name = sys.argv[1], sys.argv[2], sys.argv[3]
config = yaml.safe_load(open(f"{k8s}/configmap.yaml"))
deployment = yaml.safe_load(open(f"{k8s}/deployment.yaml"))
secret = yaml.safe_load(open(f"{k8s}/secret.example.yaml"))
deployment["metadata"]["name"] = name
deployment["spec"]["replicas"] = int(sys.argv[4])
pod = deployment["spec"]["template"]["spec"]
container = pod["containers"][0]
# The timeline's store by address (podman gives pods no Service names), under a prefix of this run.
args = container["args"]
args[args.index("--timeline") + 1] = f"etcd://{sys.argv[5]}:2379/ocean/{name}"
# podman publishes every containerPort on the host (as hostPort), so replicas would collide;
# the pods are reached on their own IPs instead. The probes then name the port by number.
del container["ports"]
for probe in ("startupProbe", "livenessProbe", "readinessProbe"):
    container[probe]["httpGet"]["port"] = 9464
# podman keeps each ConfigMap and Secret volume as a named volume: names of this run's own, so
# that the cleanup removes exactly them.
config["metadata"]["name"] = f"{name}-config"
for volume in pod["volumes"]:
    if "configMap" in volume:
        volume["configMap"]["name"] = f"{name}-config"
    if "secret" in volume:
        # podman 4.3 reads the Secret from its own store (`podman secret create`, below); a
        # missing `optional` crashes it; it ignores fsGroup, so 0440 root:root would be
        # unreadable by uid 10001.
        volume["secret"]["secretName"] = f"{name}-secrets"
        volume["secret"]["optional"] = False
        volume["secret"]["defaultMode"] = 0o444
secret["metadata"]["name"] = f"{name}-secrets"
# podman 4.3 ignores `stringData` and writes `data` values as they are, without base64-decoding.
del secret["stringData"]
secret["data"] = {k: secrets.token_hex(32) for k in ("admin-token", "cookie-key")}
yaml.safe_dump(secret, open(out + ".secret", "w"), sort_keys=False)
yaml.safe_dump_all([config, deployment], open(out, "w"), sort_keys=False)
EOF
pm secret create "$name-secrets" "$kube_file.secret" > /dev/null
pm kube play "$kube_file" > "$work/kube.log" 2>&1 || { cat "$work/kube.log" >&2; fail "podman kube play of the derived deploy/k8s manifest failed"; }
pods=()
for ((i = 0; i < replicas; ++i)); do pods+=("$name-pod-$i"); done
servers=()
for pod in "${pods[@]}"; do
  infra=$(pm pod inspect --format '{{.InfraContainerID}}' "$pod") || fail "podman kube play made no pod $pod"
  ip=$(pm inspect --format "{{range .NetworkSettings.Networks}}{{.IPAddress}} {{end}}" "$infra" | awk "{print \$1}")
  [[ -n "$ip" ]] || fail "pod $pod has no IP address"
  wait_ready "http://$ip:9464/readyz" "$pod-ocean-server"
  servers+=("$ip:7700")
done
say "kube play: $replicas replicas ready at ${servers[*]}"

# Every pod computes the same sea: frames of the same tick, byte for byte, decoding to the same
# heights (as test_replica checks for processes) - across a change made through one of them, which
# the timeline brings to all (the test runs OCEAN_REPLICA_CHANGE once the recordings are keyed).
replica_list=$(IFS=,; echo "${servers[*]}")
python3 -c 'import sys, yaml; print(yaml.safe_load(open(sys.argv[1]))["data"]["admin-token"])' "$kube_file.secret" \
  > "$work/admin-token"
OCEAN_REPLICA_SERVERS=$replica_list OCEAN_REPLICA_PROFILES=mobile,desktop \
  OCEAN_REPLICA_CHANGE="$admin --server ${servers[1]} --token-file $work/admin-token --wind-speed 15 --wind-dir 45" \
  "$replica_test" "[external]" > "$work/replicas.log" 2>&1 ||
  { cat "$work/replicas.log" >&2; fail "the $replicas replicas did not send byte-identical frames across a change (above)"; }
grep -h '^\[replica\]' "$work/replicas.log" | while read -r line; do say "$line"; done
for server in "${servers[@]}"; do
  applied=$(curl -fsS --max-time 2 "http://${server%:*}:9464/metrics" | awk '$1 == "ocean_timeline_entries_total" {print $2}')
  [[ "$applied" == 1 ]] || fail "replica $server applied ${applied:-no} timeline entries, not the 1 change made through ${servers[1]}"
done
say "kube play: the change through ${servers[1]} was applied by all $replicas replicas (ocean_timeline_entries_total 1 each)"

# The clients start on the first replica; after 4 s that pod is removed, so each must fail over.
"$loadtest" --json --quiet --server "${servers[0]},${servers[1]}" --clients 5 --duration 12 --transport tcp \
  > "$work/failover.json" 2> "$work/failover.json.err" &
loadtest_pid=$!
sleep 4
pm pod rm -f -t 0 "${pods[0]}" > /dev/null 2>> "$work/run.log" || fail "could not remove pod ${pods[0]}"
say "removed pod ${pods[0]}"
wait "$loadtest_pid" || { cat "$work/failover.json.err" >&2; fail "ocean-loadtest across the 2 replicas exited non-zero"; }
check_load "$work/failover.json" "failover between 2 of the replicas" 5 5 || fail "failover from the removed replica did not pass (above)"
say "passed in $((SECONDS - stage_start)) s"
