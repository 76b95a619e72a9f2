#!/usr/bin/env python3
"""A stand-in team for match tests: one T1 per number that answers (syn) every cycle and nothing else.
usage: syn-agent.py HOST PORT TEAM N [N ...]"""
import socket, struct, sys, threading

def frame(s):
    head = b''
    while len(head) < 4:
        c = s.recv(4 - len(head))
        if not c:
            raise EOFError
        head += c
    n = struct.unpack('>I', head)[0]
    body = b''
    while len(body) < n:
        c = s.recv(n - len(body))
        if not c:
            raise EOFError
        body += c
    return body

def send(s, m):
    s.sendall(struct.pack('>I', len(m)) + m)

def player(host, port, team, n):
    s = socket.create_connection((host, port))
    send(s, b'(init T1 %s %d)' % (team.encode(), n))
    try:
        while True:
            frame(s)
            send(s, b'(syn)')
    except (EOFError, OSError):
        pass

host, port, team = sys.argv[1], int(sys.argv[2]), sys.argv[3]
threads = [threading.Thread(target=player, args=(host, port, team, int(n))) for n in sys.argv[4:]]
for t in threads:
    t.start()
for t in threads:
    t.join()
