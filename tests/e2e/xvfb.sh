#!/usr/bin/env bash
# ctest fixture: one Xvfb for the whole test run (parallel xvfb-run calls race for a
# display number). `xvfb.sh start DIR` writes DIR/display (e.g. ":199"); `stop DIR` ends it.
set -euo pipefail
cmd=$1 dir=$2
mkdir -p "$dir"
case "$cmd" in
start)
  if [ -f "$dir/pid" ] && kill -0 "$(cat "$dir/pid")" 2>/dev/null; then exit 0; fi
  rm -f "$dir/display"
  # A display number of our own, away from :0 and spread by PID: with -displayfd a new
  # server takes the lowest free number, often the one a just-stopped server (another test
  # run's) still cleans up, which can remove the new server's socket. -noreset: by default
  # the server resets whenever its last client leaves, and a test connecting during the
  # reset cannot open the display.
  for attempt in $(seq 0 40); do
    n=$(( 100 + ($$ + attempt * 37) % 800 ))
    [ -e "/tmp/.X$n-lock" ] && continue
    Xvfb ":$n" -screen 0 1280x900x24 -nolisten tcp -noreset >"$dir/xvfb.log" 2>&1 &
    pid=$!
    # Tests start as soon as this returns: wait until the server takes clients.
    for _ in $(seq 1 100); do
      if DISPLAY=":$n" xdotool getdisplaygeometry >/dev/null 2>&1; then
        echo "$pid" > "$dir/pid"
        echo ":$n" > "$dir/display"
        echo "Xvfb on :$n"
        exit 0
      fi
      kill -0 "$pid" 2>/dev/null || break  # display taken meanwhile: try another
      sleep 0.1
    done
    kill "$pid" 2>/dev/null || true
  done
  echo "Xvfb did not start: $(cat "$dir/xvfb.log")" >&2
  exit 1 ;;
stop)
  if [ -f "$dir/pid" ]; then kill "$(cat "$dir/pid")" 2>/dev/null || true; rm -f "$dir/pid"; fi ;;
*) echo "usage: xvfb.sh start|stop DIR" >&2; exit 2 ;;
esac
