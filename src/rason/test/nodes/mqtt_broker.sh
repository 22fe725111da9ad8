#!/bin/sh
# A mosquitto for a rostest: anonymous, no persistence, on 127.0.0.1:PORT (the first argument;
# roslaunch's own arguments after it are ignored). Its configuration lives in a temporary file.
port=${1:?usage: mqtt_broker.sh PORT}
conf=$(mktemp "${TMPDIR:-/tmp}/rason-mosquitto.XXXXXX")
trap 'rm -f "$conf"' EXIT INT TERM
printf 'listener %s 127.0.0.1\nallow_anonymous true\npersistence false\nset_tcp_nodelay true\nlog_dest stderr\n' "$port" > "$conf"
for bin in /usr/sbin/mosquitto /usr/bin/mosquitto mosquitto; do
  if command -v "$bin" >/dev/null 2>&1; then
    "$bin" -c "$conf" &
    pid=$!
    trap 'kill $pid 2>/dev/null; rm -f "$conf"' EXIT INT TERM
    wait $pid
    exit $?
  fi
done
echo "mqtt_broker.sh: mosquitto is not installed (apt-get install -y mosquitto)" >&2
exit 1
