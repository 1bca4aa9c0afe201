"""Export a Blender scene's active camera as a Photopic "camera track" (JSON).

Run with Blender (tested with 3.4.1):

    blender -b scene.blend --python tools/blender/photopic_camera.py -- -o track.json [--frames A-B]

--frames defaults to the scene's frame_start..frame_end ("A" alone is one frame). The
script evaluates every frame (scene.frame_set) and writes, atomically (temporary file in
the same folder, then os.replace):

    {
      "fps": 24.0,
      "source": "Blender 3.4.1, scene.blend, camera 'Camera'",
      "frames": {
        "1": {
          "cameraToWorld": [[r00, r01, r02, t0], [r10, r11, r12, t1], [r20, r21, r22, t2], [0, 0, 0, 1]],
          "focalLengthMm": 50.0,
          "sensor": {"widthMm": 36.0, "heightMm": 24.0, "fit": "auto"},
          "shift": [0.0, 0.0],
          "near": 0.1, "far": 100.0,
          "lens": {"fNumber": 1.0, "focusDistance": 1.53, "shutterAngleDeg": 180.0},
          "sunDirection": [x, y, z]
        }
      }
    }

Conventions
-----------
* World space is Y-up and right-handed (OpenGL): Blender's Z-up world point (x, y, z) is
  (x, z, -y) in the track. Camera space is OpenGL's: the camera looks down -Z, +Y is up
  in the image, +X is right. A Blender camera object's local axes are already these, so
  cameraToWorld = C @ M, where M is camera.matrix_world with any object scale removed
  (its rotation columns normalised) and C = [[1,0,0,0],[0,0,1,0],[0,-1,0,0],[0,0,0,1]].
  The matrix is row-major: "cameraToWorld"[i] is row i, the translation is the last
  column, and a camera-space point p maps to the world as cameraToWorld @ [p, 1].
* "focalLengthMm" is camera.data.lens. Only perspective cameras are exported; an
  orthographic or panoramic camera is an error.
* "sensor" is sensor_width / sensor_height in millimetres and "fit" is sensor_fit in
  lower case: "auto", "horizontal" or "vertical". How Blender uses them (for a render of
  W x H pixels with square pixels):
    - "auto": the sensor WIDTH (sensor_height is ignored) spans the larger image side:
      W when W >= H, else H;
    - "horizontal": sensor width spans W;  "vertical": sensor height spans H.
  So with "auto" and W >= H the focal length in pixels is focalLengthMm / widthMm * W for
  both axes, and the vertical field of view follows from H.
* "shift" is [shift_x, shift_y] exactly as Blender stores them: fractions of the fitted
  image side (the larger side for "auto", W for "horizontal", H for "vertical"). A
  positive shift_x moves the view window right (the optical axis lands left of the image
  centre), a positive shift_y moves it up.
* "near" / "far" are clip_start / clip_end in scene units.
* "lens": "fNumber" (dof.aperture_fstop) and "focusDistance" appear only when the
  camera's depth of field is on. With a focus object the focus distance is measured as
  Cycles does: |dot(view axis, object position - camera position)|, the planar distance
  along the view axis, not the Euclidean one; otherwise it is dof.focus_distance.
  "shutterAngleDeg" is render.motion_blur_shutter * 360 (Blender's shutter is in frames)
  and is always written (whether Photopic blurs is its own motionBlur.enabled setting).
* "sunDirection": a unit vector in the Y-up world pointing TOWARDS the sun, from the
  first (by object name) SUN light that renders (not hide_render, in the view layer). A
  sun shines along its local -Z, so this is its matrix_world +Z axis, converted to Y-up.
  Omitted when the scene has no such sun.
* "fps" is render.fps / render.fps_base.
* Numbers are plain JSON numbers with at most 7 significant digits (rotation and
  direction entries are rounded to 7 decimals, so 1e-8 noise becomes 0).
"""

import argparse
import json
import math
import os
import re
import sys
import tempfile

import bpy
from mathutils import Matrix

# Blender Z-up world -> Y-up world: (x, y, z) -> (x, z, -y).
Z_UP_TO_Y_UP = Matrix(((1.0, 0.0, 0.0, 0.0),
                       (0.0, 0.0, 1.0, 0.0),
                       (0.0, -1.0, 0.0, 0.0),
                       (0.0, 0.0, 0.0, 1.0)))


class ExportError(Exception):
    pass


def fail(message):
    print("photopic_camera.py: error: " + message, file=sys.stderr, flush=True)
    sys.exit(1)


def parse_args(scene):
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(
        prog="photopic_camera.py",
        description="Export the active scene camera as a Photopic camera track (JSON).")
    p.add_argument("-o", "--output", required=True, help="the JSON file to write")
    p.add_argument("--frames", help="A-B or A (default: the scene's frame range)")
    args = p.parse_args(argv)
    if args.frames is None:
        args.first, args.last = scene.frame_start, scene.frame_end
    else:
        try:
            parts = args.frames.split("-")
            if len(parts) == 1:
                first = last = int(parts[0])
            elif len(parts) == 2:
                first, last = int(parts[0]), int(parts[1])
            else:
                raise ValueError
        except ValueError:
            fail("bad --frames %r: expected A-B or A with integer frames" % args.frames)
        if first > last:
            fail("bad --frames %r: the first frame is after the last" % args.frames)
        args.first, args.last = first, last
    return args


def num(v):
    """A float with at most 7 significant digits (no -0.0)."""
    v = float(v)
    if not math.isfinite(v):
        raise ExportError("a non-finite number (%r) in the camera data" % v)
    r = float("%.7g" % v)
    return 0.0 if r == 0.0 else r


def unit(v):
    """An entry of a rotation or unit vector: 7 decimals, then 7 significant digits."""
    return num(round(float(v), 7))


def camera_to_world(cam_obj):
    m = cam_obj.matrix_world.copy()
    for c in range(3):
        col = m.col[c].xyz
        length = col.length
        if length == 0.0:
            raise ExportError("camera '%s' has a zero scale" % cam_obj.name)
        m.col[c].xyz = col / length
    m = Z_UP_TO_Y_UP @ m
    rows = []
    for i in range(4):
        rows.append([unit(m[i][j]) for j in range(3)] + [num(m[i][3]) if i < 3 else 1.0])
    rows[3] = [0.0, 0.0, 0.0, 1.0]
    return rows


def focus_distance(cam_obj):
    dof = cam_obj.data.dof
    target = dof.focus_object
    if target is None:
        return dof.focus_distance
    target_pos = target.matrix_world.translation
    sub = getattr(dof, "focus_subtarget", "")  # Blender 4.x: a bone of an armature
    if sub and target.type == "ARMATURE" and sub in target.pose.bones:
        target_pos = target.matrix_world @ target.pose.bones[sub].head
    view_axis = cam_obj.matrix_world.col[2].xyz.normalized()  # +Z: opposite to the view
    return abs(view_axis.dot(cam_obj.matrix_world.translation - target_pos))


def sun_direction(scene, view_layer):
    suns = [o for o in scene.objects
            if o.type == "LIGHT" and o.data.type == "SUN" and not o.hide_render
            and o.name in view_layer.objects]
    if not suns:
        return None
    sun = min(suns, key=lambda o: o.name)
    z = sun.matrix_world.col[2].xyz
    if z.length == 0.0:
        raise ExportError("sun '%s' has a zero scale" % sun.name)
    z = z.normalized()
    return [unit(z.x), unit(z.z), unit(-z.y)]


def frame_record(scene, view_layer, cam_obj):
    cam = cam_obj.data
    lens = {}
    if cam.dof.use_dof:
        lens["fNumber"] = num(cam.dof.aperture_fstop)
        lens["focusDistance"] = num(focus_distance(cam_obj))
    lens["shutterAngleDeg"] = num(scene.render.motion_blur_shutter * 360.0)
    rec = {
        "cameraToWorld": camera_to_world(cam_obj),
        "focalLengthMm": num(cam.lens),
        "sensor": {"widthMm": num(cam.sensor_width), "heightMm": num(cam.sensor_height),
                   "fit": cam.sensor_fit.lower()},
        "shift": [num(cam.shift_x), num(cam.shift_y)],
        "near": num(cam.clip_start),
        "far": num(cam.clip_end),
        "lens": lens,
    }
    sun = sun_direction(scene, view_layer)
    if sun is not None:
        rec["sunDirection"] = sun
    return rec


def check_camera(cam_obj, frame):
    if cam_obj is None:
        raise ExportError("the scene has no active camera (scene.camera is None) at frame %d"
                          % frame)
    if cam_obj.type != "CAMERA":
        raise ExportError("the scene camera '%s' is a %s object, not a camera"
                          % (cam_obj.name, cam_obj.type))
    if cam_obj.data.type != "PERSP":
        raise ExportError("camera '%s' is %s; only perspective cameras can be exported"
                          % (cam_obj.name, cam_obj.data.type))


def write_atomically(path, text):
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        raise ExportError("the output folder %s does not exist" % folder)
    fd, tmp = tempfile.mkstemp(prefix=".photopic_camera.", suffix=".tmp", dir=folder)
    try:
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it 0600
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def main():
    scene = bpy.context.scene
    view_layer = bpy.context.view_layer
    args = parse_args(scene)
    if scene.camera is None:
        fail("the scene '%s' has no active camera (scene.camera is None)" % scene.name)
    if scene.render.fps_base == 0:
        fail("the scene's render.fps_base is 0")
    keep_frame = scene.frame_current
    frames = {}
    names = set()
    try:
        for f in range(args.first, args.last + 1):
            scene.frame_set(f)
            cam_obj = scene.camera  # markers may switch cameras
            check_camera(cam_obj, f)
            names.add(cam_obj.name)
            frames[str(f)] = frame_record(scene, view_layer, cam_obj)
    except ExportError as e:
        fail(str(e))
    finally:
        scene.frame_set(keep_frame)
    blend = os.path.basename(bpy.data.filepath) or "(unsaved scene)"
    cams = ", ".join("'%s'" % n for n in sorted(names))
    track = {
        "fps": num(scene.render.fps / scene.render.fps_base),
        "source": "Blender %s, %s, camera%s %s" % (bpy.app.version_string, blend,
                                                  "s" if len(names) > 1 else "", cams),
        "frames": frames,
    }
    text = json.dumps(track, indent=2) + "\n"
    # One line per innermost array of numbers (matrix rows, vectors).
    text = re.sub(r"\[\s+([^\[\]{}\"]*?)\s+\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)
    try:
        write_atomically(args.output, text)
    except (ExportError, OSError) as e:
        fail("cannot write %s: %s" % (args.output, e))
    print("photopic_camera.py: wrote %d frame(s) to %s" % (len(frames), args.output))


if __name__ == "__main__":
    main()
