"""A small client of `morphogen breed`'s HTTP API (docs/breed-api.md), for the
scripts that measure the grids and breed by hand from a terminal."""
import json
import subprocess
import time
import urllib.request


class Breed:
    def __init__(self, morphogen, args):
        self.proc = subprocess.Popen([morphogen, "breed", *args, "--no-browser"], stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, text=True)
        url = self.proc.stdout.readline().strip()
        self.base, self.token = url.split("/?token=")

    def call(self, method, path, body=None):
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(self.base + path, data=data, method=method,
                                     headers={"Authorization": "Bearer " + self.token,
                                              "Content-Type": "application/json"})
        with urllib.request.urlopen(req, timeout=3600) as r:
            return json.loads(r.read())

    def state(self):
        return self.call("GET", "/api/state")

    def breed(self, parents, strength):
        return self.call("POST", "/api/breed", {"parents": parents, "strength": strength})

    def explore(self, parents, births, along=None):
        body = {"parents": parents, "births": births}
        if along:
            body["along"] = along
        self.call("POST", "/api/explore", body)
        while True:
            time.sleep(0.5)
            s = self.state()
            if not s["search"]["running"]:
                return s

    def export(self, pid):
        return self.call("POST", "/api/export", {"id": pid})

    def close(self):
        self.proc.terminate()
        self.proc.wait()


def describe(p):
    m = p["measures"]
    f = p["fitness"]
    return "%s h=%.2f tips=%s limbs=%s fork=%s fit=%s" % (
        p["id"], m.get("height", 0), int(m["tips"]) if "tips" in m else "-",
        int(m["limbs"]) if "limbs" in m else "-",
        "%.2f" % m["first_fork"] if "first_fork" in m else "-", "%.3g" % f if f is not None else "invalid")
