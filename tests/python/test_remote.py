"""YADE's remote access is off unless asked for (patches/yade-remote-opt-in.patch): a run opens no
listening socket; with YADE_REMOTE=1 the Python prompt and the info provider listen on the loopback
interface only, and the prompt takes its 128-bit cookie and nothing else."""
import os
import re
import shutil
import socket
import subprocess
import time

import pytest
from conftest import REPO

LISTENING = '''
import os, re
inodes = set()
for fd in os.listdir("/proc/self/fd"):
    try:
        target = os.readlink(f"/proc/self/fd/{fd}")
    except OSError:  # the listing's own descriptor, closed by now
        continue
    if target.startswith("socket:"):
        inodes.add(int(target[8:-1]))
for table in ("/proc/net/tcp", "/proc/net/tcp6"):
    for row in open(table).read().splitlines()[1:]:
        field = row.split()
        if field[3] == "0A" and int(field[9]) in inodes:  # LISTEN, one of this process's sockets
            print("LISTEN", field[1], flush=True)
print("READY", flush=True)
'''


def start(tmp_path, remote: bool, linger: float = 0.0) -> subprocess.Popen:
    """A ./yade run that prints its own listening sockets (address:port in /proc's hex), then stays
    ``linger`` seconds."""
    script = tmp_path / "listening.py"
    script.write_text(LISTENING + f"import time; time.sleep({linger})\n")
    env = dict(os.environ, YADE_REMOTE="1" if remote else "0")
    return subprocess.Popen([os.path.join(REPO, "yade"), "-x", "-n", "-j1", str(script)], env=env, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def listening(proc: subprocess.Popen) -> list[str]:
    sockets = []
    for line in proc.stdout:
        if line.startswith("READY"):
            return sockets
        if line.startswith("LISTEN"):
            sockets.append(line.split()[1])
    raise AssertionError("the run ended before it listed its sockets: " + proc.stderr.read()[-2000:])


def test_a_default_run_listens_on_no_port(tmp_path):
    proc = start(tmp_path, remote=False)
    assert listening(proc) == []
    assert proc.wait(timeout=60) == 0


@pytest.fixture
def remote_run(tmp_path):
    """A run with YADE_REMOTE=1 for 60 s: its sockets, the prompt's port and cookie."""
    proc = start(tmp_path, remote=True, linger=60)
    sockets = listening(proc)
    prompt = None
    while prompt is None:
        prompt = re.match(r"TCP python prompt on ([\d.]+):(\d+), auth cookie `(\w+)'", proc.stderr.readline())
    yield sockets, prompt.group(1), int(prompt.group(2)), prompt.group(3)
    proc.kill()
    proc.wait()


def session(port: int, cookie: str, command: str) -> str:
    with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
        assert s.recv(100).startswith(b"Enter auth cookie")
        s.sendall(cookie.encode() + b"\n")
        reply = b""
        try:
            while b">>> " not in reply:
                chunk = s.recv(4096)
                if not chunk:
                    return reply.decode()  # the server closed the connection
                reply += chunk
            s.sendall(command.encode() + b"\n")
            time.sleep(0.5)
            return reply.decode() + s.recv(4096).decode()
        except socket.timeout:
            return reply.decode()


def test_remote_access_listens_on_loopback_only_with_a_128_bit_cookie(remote_run):
    sockets, host, port, cookie = remote_run
    assert len(sockets) == 2 and all(s.startswith("0100007F:") for s in sockets)  # 127.0.0.1, both servers
    assert host == "127.0.0.1" and re.fullmatch(r"[0-9a-f]{32}", cookie)


def test_the_prompt_takes_the_right_cookie_and_refuses_a_wrong_one(remote_run):
    _, _, port, cookie = remote_run
    command = "print('in' + 'side')"  # its output, "inside", cannot be a port number in the server's farewell
    assert "inside" in session(port, cookie, command)
    refused = session(port, "0" * 32, command)
    assert ">>> " not in refused and "inside" not in refused


def test_a_client_in_another_network_namespace_cannot_connect(remote_run):
    if os.geteuid() != 0 or not shutil.which("ip"):
        pytest.skip("needs root and iproute2 to make a network namespace")
    _, _, port, _ = remote_run
    ns, host, guest = "toppling-remote-test", "10.231.9.1", "10.231.9.2"

    def ip(*args):
        subprocess.run(["ip", *args], check=True, capture_output=True)

    subprocess.run(["ip", "netns", "del", ns], capture_output=True)
    ip("netns", "add", ns)
    try:
        ip("link", "add", "tpl-host", "type", "veth", "peer", "name", "tpl-guest")
        ip("link", "set", "tpl-guest", "netns", ns)
        ip("addr", "add", f"{host}/24", "dev", "tpl-host")
        ip("link", "set", "tpl-host", "up")
        ip("netns", "exec", ns, "ip", "addr", "add", f"{guest}/24", "dev", "tpl-guest")
        ip("netns", "exec", ns, "ip", "link", "set", "tpl-guest", "up")
        probe = ("import socket, sys\ns = socket.socket()\ns.settimeout(5)\n"
                 f"sys.exit(s.connect_ex(('{host}', {port})))\n")
        reached = subprocess.run(["ip", "netns", "exec", ns, "python3", "-c", probe], capture_output=True)
        assert reached.returncode != 0  # refused: nothing listens on the host's outside address
        here = socket.socket()
        here.settimeout(5)
        assert here.connect_ex((host, port)) != 0  # nor from this side, by that address
        here.close()
    finally:
        subprocess.run(["ip", "link", "del", "tpl-host"], capture_output=True)
        subprocess.run(["ip", "netns", "del", ns], capture_output=True)


def test_yade_batch_runs_a_table_without_listening_and_reports_both_jobs_done(tmp_path):
    script = tmp_path / "job.py"
    script.write_text("from yade.utils import readParamsFromTable\nreadParamsFromTable(value=0, noTableOk=True)\n"
                      "from yade.params import table\n"
                      f"open('{tmp_path}/done_' + str(table.value), 'w').write('ok')\n")
    (tmp_path / "jobs.table").write_text("value\n1\n2\n")
    env = dict(os.environ, YADE_REMOTE="0")
    proc = subprocess.run([os.path.join(REPO, "yade-batch"), "-j2", "--log", f"{tmp_path}/@.log",
                           str(tmp_path / "jobs.table"), str(script)], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr[-2000:]
    assert sorted(p.name for p in tmp_path.glob("done_*")) == ["done_1", "done_2"]
    assert "http://" not in proc.stdout  # no status page unless asked for
    assert proc.stdout.count("finished") >= 2 or "All jobs finished" in proc.stdout
