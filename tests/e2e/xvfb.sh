#!/usr/bin/env bash
# ctest fixture: one Xvfb for the whole test run (parallel xvfb-run calls race for a
# display number). `xvfb.sh start DIR` writes DIR/display (e.g. ":99"); `stop DIR` ends it.
set -euo pipefail
cmd=$1 dir=$2
mkdir -p "$dir"
case "$cmd" in
start)
  if [ -f "$dir/pid" ] && kill -0 "$(cat "$dir/pid")" 2>/dev/null; then exit 0; fi
  rm -f "$dir/display.raw" "$dir/display"
  # -displayfd lets Xvfb pick a free display and tell us which.
  Xvfb -displayfd 3 -screen 0 1280x900x24 -nolisten tcp 3>"$dir/display.raw" >"$dir/xvfb.log" 2>&1 &
  echo $! > "$dir/pid"
  for _ in $(seq 1 100); do
    if [ -s "$dir/display.raw" ]; then
      display=":$(head -n 1 "$dir/display.raw" | tr -d '[:space:]')"
      # Tests start as soon as this returns: wait until the server takes clients.
      for _ in $(seq 1 100); do
        if DISPLAY=$display xdotool getdisplaygeometry >/dev/null 2>&1; then
          echo "$display" > "$dir/display"
          echo "Xvfb on $display"
          exit 0
        fi
        sleep 0.1
      done
      echo "Xvfb announced $display but takes no clients: $(cat "$dir/xvfb.log")" >&2
      exit 1
    fi
    sleep 0.1
  done
  echo "Xvfb did not start: $(cat "$dir/xvfb.log")" >&2
  exit 1 ;;
stop)
  if [ -f "$dir/pid" ]; then kill "$(cat "$dir/pid")" 2>/dev/null || true; rm -f "$dir/pid"; fi ;;
*) echo "usage: xvfb.sh start|stop DIR" >&2; exit 2 ;;
esac
