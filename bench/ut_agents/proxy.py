#!/usr/bin/env python3
"""Transparent TCP proxy for the SimSpark agent protocol (4-byte big-endian length + S-expression payload).

Forwards complete frames unchanged in both directions (each logged before it is forwarded) and logs every complete message as one JSON line:
  {"dir": "s2a"|"a2s", "cyc": N, "wall": unix_time, "msg": "<payload>"}
cyc = number of server->agent messages seen so far (s2a message k has cyc k, starting at 0; an a2s message has
the cyc of the last perception the agent had received when the proxy read it).
usage: proxy.py LISTEN_PORT SERVER_PORT OUT.jsonl [SERVER_HOST=127.0.0.1]
Accepts one agent connection (then stops listening); exits when either side closes.
"""
import json, socket, struct, sys, threading, time

lp, sp, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
host = sys.argv[4] if len(sys.argv) > 4 else '127.0.0.1'
lock = threading.Lock()
state = {'cyc': -1}
f = open(out, 'w')


def pump(src, dst, direction):
    # Log each complete frame BEFORE forwarding it, so that the log order is causal (a reply is always logged
    # before the perception the server sends after receiving it).  Only complete frames are forwarded.
    buf = b''
    try:
        while True:
            data = src.recv(65536)
            if not data:
                break
            buf += data
            while len(buf) >= 4:
                n = struct.unpack('>I', buf[:4])[0]
                if len(buf) < 4 + n:
                    break
                frame, buf = buf[:4 + n], buf[4 + n:]
                with lock:
                    if direction == 's2a':
                        state['cyc'] += 1
                    f.write(json.dumps({'dir': direction, 'cyc': state['cyc'], 'wall': time.time(),
                                        'msg': frame[4:].decode('latin-1')}) + '\n')
                    f.flush()
                dst.sendall(frame)
    except OSError:
        pass
    finally:
        for s in (src, dst):
            try:
                s.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass


ls = socket.socket()
ls.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
ls.bind(('127.0.0.1', lp))
ls.listen(1)
print(f'proxy listening on {lp} -> {host}:{sp}, log {out}', flush=True)
a, _ = ls.accept()
ls.close()
s = socket.create_connection((host, sp))
for x in (a, s):
    x.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
t1 = threading.Thread(target=pump, args=(a, s, 'a2s'))
t2 = threading.Thread(target=pump, args=(s, a, 's2a'))
t1.start(); t2.start(); t1.join(); t2.join()
with lock:
    f.close()
print('proxy done', flush=True)
