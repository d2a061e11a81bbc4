#!/usr/bin/env python3
# The ParaView plugin against `aniso render`: a mesh written by ParaView's own writer is drawn by
# pvbatch (alone, or on several MPI ranks each drawing its partition, composited by IceT) with
# the "Aniso Surface" representation and by `aniso render`, with the same camera, material,
# environment and samples (one frame, no jitter); the images must agree within BOUND relative
# L2 over the pixels the surface covers whole (the coverage of `aniso render`'s transparent
# background, less a pixel at the silhouette). With --server PVPYTHON, pvserver (on --ranks MPI
# ranks) draws and pvpython, its client, steers it and saves the image.
#   test_paraview_render.py --aniso EXE --plugin SO --pythonpath DIR --work DIR
#                           [--ranks N] [--mesh sphere|sphere-tangents|contour]
#                           [--library [--maps]]
#                           [--server PVPYTHON]
# --maps: the library material has a normal map (grooves) and an albedo map (a checker), PNG
# files VTK's writer makes here, on a sphere with ParaView's texture coordinates; the maps must
# change `aniso render`'s image by far more than the bound, so that the match is of the maps.
import argparse
import json
import os
import socket
import subprocess
import sys
import time

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter

BOUND = 0.01
SIZE = 256
SAMPLES = 64
HERE = os.path.dirname(os.path.abspath(__file__))


def run(command, env):
    print("+ " + " ".join(command), flush=True)
    # mpirun forwards its standard input to rank 0; inherited, it can hold the job up.
    result = subprocess.run(command, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, check=False)
    print(result.stdout[-4000:], flush=True)
    if result.returncode != 0:
        sys.exit("test_paraview_render: %s exited with %d" % (command[0], result.returncode))
    return result.stdout


def start_server(ranks, env, log):
    """Starts pvserver (under mpirun for several ranks) on a free port of this host and waits
    until it accepts a client; returns the process and the port."""
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        port = probe.getsockname()[1]
    command = ["pvserver", "--server-port=%d" % port]
    if ranks > 1:
        command = ["mpirun", "--oversubscribe", "--timeout", "300", "-np", str(ranks), "-x",
                   "PYTHONPATH"] + command
    print("+ " + " ".join(command), flush=True)
    server = subprocess.Popen(command, env=env, stdin=subprocess.DEVNULL, stdout=log,
                              stderr=subprocess.STDOUT)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        if server.poll() is not None:
            break
        with open(log.name, encoding="utf-8", errors="replace") as f:
            if "Accepting connection" in f.read():
                return server, port
        time.sleep(0.2)
    server.kill()
    with open(log.name, encoding="utf-8", errors="replace") as f:
        print(f.read()[-4000:])
    sys.exit("test_paraview_render: pvserver did not start")


def write_png(path, pixels):
    """Writes an 8-bit RGB image (rows from the top, as files store them) with VTK's writer."""
    height, width, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    # VTK's image rows run from the bottom.
    flat = np.ascontiguousarray(pixels[::-1].reshape(-1, 3)).astype(np.uint8)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(flat, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def write_maps(directory):
    """A normal map of grooves along u (32 across the texture) and an albedo map of a checker."""
    size = 256
    u = (np.arange(size) + 0.5) / size
    slope = 0.6 * np.cos(2.0 * np.pi * 32.0 * u)
    normal = np.stack([-slope, np.zeros(size), np.ones(size)], axis=1)
    normal /= np.linalg.norm(normal, axis=1, keepdims=True)
    normals = np.broadcast_to(np.round(255.0 * (0.5 + 0.5 * normal)), (size, size, 3))
    write_png(os.path.join(directory, "grooves.png"), normals)
    cells = ((np.arange(size) // 32)[:, None] + (np.arange(size) // 32)[None, :]) % 2
    albedo = np.where(cells[..., None] == 1, [230.0, 200.0, 120.0], [60.0, 90.0, 200.0])
    write_png(os.path.join(directory, "checker.png"), albedo)


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    if width * height <= 1:
        sys.exit("test_paraview_render: cannot read " + path)
    pixels = numpy_support.vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1).astype(np.float64)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--aniso", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--pythonpath", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--mesh", default="sphere")
    parser.add_argument("--library", action="store_true")
    parser.add_argument("--maps", action="store_true")
    parser.add_argument("--server", metavar="PVPYTHON")
    a = parser.parse_args()
    if a.maps and not a.library:
        parser.error("--maps needs --library")

    os.makedirs(a.work, exist_ok=True)
    env = dict(os.environ)
    env["PYTHONPATH"] = a.pythonpath
    if os.getuid() == 0:
        env["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
        env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    kind = "sphere-uv" if a.maps else a.mesh
    mesh = os.path.join(a.work, kind + ".vtp")
    run(["pvbatch", os.path.join(HERE, "pv_mesh.py"), kind, mesh], env)

    material = []
    pv_material = []
    if a.library:
        # A material of a library file as the application writes one, turned about Z.
        library = os.path.join(a.work, "library.json")
        brass = {"nu": 3000, "nv": 40, "f0": [0.91, 0.78, 0.42], "albedo": [0.02, 0.015, 0.01],
                 "tangents": "around:0,0,1"}
        plain = dict(brass)
        if a.maps:
            # Paths relative to the library, as the application writes them.
            write_maps(a.work)
            brass.update({"albedo": [0.4, 0.4, 0.4], "bump": "normal",
                          "normal-map": "grooves.png", "albedo-map": "checker.png"})
            plain["albedo"] = brass["albedo"]
        with open(library, "w", encoding="utf-8") as f:
            json.dump({"format": "aniso-materials", "version": 1,
                       "materials": {"turned brass": brass, "plain brass": plain}}, f)
        material = ["--materials", library, "--part", "*=turned brass"]
        pv_material = [library, "turned brass"]

    reference = os.path.join(a.work, "aniso.png")
    run([a.aniso, "render", mesh, "--view", "-y", "--size", "%dx%d" % (SIZE, SIZE), "--samples",
         str(SAMPLES), "--frames", "1", "--jitter", "off", "--background", "none", "-o",
         reference] + material, env)

    image = os.path.join(a.work, "paraview.png")
    arguments = [os.path.join(HERE, "pv_render.py"), a.plugin, mesh, image, str(SIZE),
                 str(SAMPLES)]
    partitioned = ["redistribute"] if a.ranks > 1 else []
    if a.server:
        with open(os.path.join(a.work, "pvserver.log"), "w+", encoding="utf-8") as log:
            server, port = start_server(a.ranks, env, log)
            try:
                out = run([a.server] + arguments + ["connect=%d" % port] + partitioned
                          + pv_material, env)
                # The server ends when its client disconnects.
                server.wait(timeout=60)
            finally:
                if server.poll() is None:
                    server.kill()
                log.seek(0)
                print("pvserver: " + log.read()[-2000:], flush=True)
        if "rendered by the server" not in out:
            sys.exit("test_paraview_render: the server did not render")
    else:
        pv = ["pvbatch"] + arguments + partitioned + pv_material
        if a.ranks > 1:
            # A rank that fails leaves the others waiting: mpirun ends the job after its timeout.
            pv = ["mpirun", "--oversubscribe", "--timeout", "300", "-np", str(a.ranks), "-x",
                  "PYTHONPATH"] + pv
        out = run(pv, env)
    if "%d rank(s)" % a.ranks not in out:
        sys.exit("test_paraview_render: ParaView did not run on %d ranks" % a.ranks)

    ours = read_png(reference)
    theirs = read_png(image)
    unmapped = None
    if a.maps:
        plain = os.path.join(a.work, "aniso-plain.png")
        run([a.aniso, "render", mesh, "--view", "-y", "--size", "%dx%d" % (SIZE, SIZE),
             "--samples", str(SAMPLES), "--frames", "1", "--jitter", "off", "--background",
             "none", "-o", plain, "--materials", library, "--part", "*=plain brass"], env)
        unmapped = read_png(plain)
    covered = ours[..., 3] == 255
    inner = covered.copy()
    inner[1:, :] &= covered[:-1, :]
    inner[:-1, :] &= covered[1:, :]
    inner[:, 1:] &= covered[:, :-1]
    inner[:, :-1] &= covered[:, 1:]
    count = int(inner.sum())
    if count < SIZE * SIZE // 10:
        sys.exit("test_paraview_render: the surface covers only %d pixels" % count)
    difference = theirs[..., :3][inner] - ours[..., :3][inner]
    error = float(np.sqrt((difference ** 2).sum() / (ours[..., :3][inner] ** 2).sum()))
    print("test_paraview_render: %s, %d rank(s)%s%s%s: relative L2 %.5f over %d pixels (bound %g), "
          "largest difference %d of 255" % (kind, a.ranks, ", pvserver and client" if a.server
                                            else "", ", library material" if a.library
                                            else "", " with maps" if a.maps else "", error, count, BOUND,
                                            int(np.abs(difference).max())))
    if unmapped is not None:
        without = unmapped[..., :3][inner] - ours[..., :3][inner]
        change = float(np.sqrt((without ** 2).sum() / (ours[..., :3][inner] ** 2).sum()))
        print("test_paraview_render: the maps change aniso render's image by %.4f" % change)
        if not change >= 10 * BOUND:
            sys.exit("test_paraview_render: the maps change the image too little to be tested")
    if not error <= BOUND:
        sys.exit("test_paraview_render: the plugin's image differs from aniso render's")


if __name__ == "__main__":
    main()
