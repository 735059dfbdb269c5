# Sourced by the GUI tests (gui_starts.sh, gui_open_no_dialog.sh).
# wait_for_window PATTERN TRIES [PID]: the first visible window whose name matches
# PATTERN, looked for every 0.2 s up to TRIES times, giving up sooner when process PID
# has exited; prints its id (empty when none came).
wait_for_window() {
  local pattern=$1 tries=$2 pid=${3:-} window=""
  for _ in $(seq "$tries"); do
    window=$(xdotool search --onlyvisible --name "$pattern" 2>/dev/null | head -n 1)
    [ -n "$window" ] && break
    if [ -n "$pid" ] && ! kill -0 "$pid" 2>/dev/null; then break; fi
    sleep 0.2
  done
  echo "$window"
}
