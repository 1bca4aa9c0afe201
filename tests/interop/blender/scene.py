"""Build Photopic's Blender interop test scene from nothing and render it with Cycles.

Run (Blender 3.4, factory settings so that no user preference leaks in):

    blender -b --factory-startup --python tests/interop/blender/scene.py -- \
        --out DIR [--variant passes|dof|mblur|mirror|all] [--frames A-B] [--size WxH] [--samples N]

(--size and --samples, 320x180 and 128 by default, let scripts/bench-cycles.sh render the same scene as
benchmark input at a frame's real size; the tests keep the defaults.)

What it makes (Blender's Z-up world, metres):

* a 6 m x 6 m ground plane at z = 0 and a 2.4 m x 0.35 m back wall standing on it at
  y = 2.2 (facing the camera), so that the world background ("sky") shows above it;
* a box sitting on the ground, two thin boxes making an L-shaped corner, a yellow sphere
  (the focus object) and a cylinder: contact regions for ambient occlusion;
* a small red sphere ("Mover", radius 0.1) that moves linearly by (+0.09, 0, +0.035) a
  frame (keyframed, linear interpolation and extrapolation) and a camera that trucks
  linearly by +0.02 along x a frame with a fixed orientation (looking along +y, tilted
  12 degrees down), so that both give motion vectors;
* a perspective 50 mm camera, 36 mm x 24 mm sensor, fit AUTO, clip 0.1-100, DoF focused
  on the yellow sphere at f/1.0 (at 320 x 180 a pixel is 0.1125 mm of sensor: the wall
  blurs by a 9 px circle, the sky by 15 px);
* a sun (angle 1 degree) and a constant grey-blue world background of strength 1;
* frames 1-5 at 24 fps (the animation; the renders below take some of them), 320 x 180
  pixels, Cycles on the CPU, 128 samples, fixed seed, no denoising, no adaptive sampling,
  at most 3 bounces; Blender's default pixel filter
  (Blackman-Harris, 1.5 px) and view transform "Standard" (EXR files hold linear scene
  values either way).

It saves the scene to DIR/scene.blend (camera DoF on, motion blur off, shutter 0.5 frames)
before rendering, so tools/blender/photopic_camera.py can be run on it. Then it renders
multilayer OpenEXR files (32-bit float, ZIP):

* passes: DoF off, motion blur off; Combined, Depth (Z), Normal, Vector and AO (world AO
  distance 0.5) -> DIR/passes/frame_####.exr for every frame of --frames (default 2-3:
  frame 3 and the one before it, all that motion blur and the checks of motion need);
* dof:    DoF on, motion blur off, Combined only -> DIR/dof/frame_0003.exr;
* mblur:  DoF off, motion blur on (shutter 0.5 frames = 180 degrees), Combined only ->
  DIR/mblur/frame_0003.exr;
* mirror: the ground made a perfect mirror (metallic 1, roughness 0, white), DoF and motion
  blur off, at most 6 bounces (diffuse 3, glossy 3) so that an object seen in the mirror
  keeps the indirect light it has seen directly; Combined, Depth, Normal and the Glossy
  Direct, Indirect and Colour passes -> DIR/mirror/frame_0003.exr. The ground's reflected
  radiance is (GlossDir + GlossInd) / GlossCol: the truth for screen-space reflections;
* all:    the four.

The time each variant took to render is printed as "render <variant>: N.N s".
"""

import argparse
import math
import os
import sys
import time

import bpy

FPS = 24
RES_X, RES_Y = 320, 180
SAMPLES = 128
EFFECT_FRAME = 3  # the frame the dof and mblur variants render
SEED = 1
AO_DISTANCE = 0.5
F_STOP = 1.0

# Linear motion per frame (Blender units), applied from the frame-1 position.
MOVER_RADIUS = 0.1
MOVER_START = (-0.55, 0.0, 0.25)
MOVER_STEP = (0.09, 0.0, 0.035)
CAMERA_START = (-0.04, -2.0, 0.6)
CAMERA_STEP = (0.02, 0.0, 0.0)
CAMERA_TILT_DEG = 12.0  # below the horizon; the camera looks along +y


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="scene.py", description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True, help="output folder")
    p.add_argument("--variant", default="all", choices=("passes", "dof", "mblur", "mirror", "all"))
    p.add_argument("--frames", default="2-3", help="frame range A-B for 'passes' (default 2-3)")
    p.add_argument("--size", default="%dx%d" % (RES_X, RES_Y), help="WxH (default %dx%d)" % (RES_X, RES_Y))
    p.add_argument("--samples", type=int, default=SAMPLES, help="Cycles samples (default %d)" % SAMPLES)
    args = p.parse_args(argv)
    try:
        args.width, args.height = (int(x) for x in args.size.split("x"))
        if args.width < 1 or args.height < 1:
            raise ValueError
    except ValueError:
        p.error("--size must be WxH with positive integers, not %r" % args.size)
    if args.samples < 1:
        p.error("--samples must be at least 1, not %d" % args.samples)
    try:
        a, b = (int(x) for x in args.frames.split("-"))
        if a > b:
            raise ValueError
    except ValueError:
        p.error("--frames must be A-B with integers A <= B, not %r" % args.frames)
    args.first, args.last = a, b
    return args


def clear_scene():
    """Remove everything the factory startup file holds (cube, light, camera, ...)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for coll in (bpy.data.meshes, bpy.data.materials, bpy.data.lights, bpy.data.cameras,
                 bpy.data.worlds):
        for block in list(coll):
            coll.remove(block)


def material(name, rgb):
    """A plain, almost diffuse principled material."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*rgb, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.9
    bsdf.inputs["Specular"].default_value = 0.2
    return mat


def add(obj_op, name, mat, location, rotation=(0.0, 0.0, 0.0), scale=(1.0, 1.0, 1.0), **kw):
    obj_op(location=location, rotation=rotation, **kw)
    obj = bpy.context.active_object
    obj.name = name
    obj.scale = scale
    obj.data.materials.append(mat)
    return obj


def build_geometry():
    """Static objects. Returns the focus object (the yellow sphere)."""
    ops = bpy.ops.mesh
    add(ops.primitive_plane_add, "Ground", material("Ground", (0.55, 0.55, 0.5)),
        (0.0, 0.0, 0.0), size=6.0)
    add(ops.primitive_plane_add, "Wall", material("Wall", (0.7, 0.45, 0.3)),
        (0.0, 2.2, 0.175), rotation=(math.radians(90.0), 0.0, 0.0), scale=(2.4, 0.35, 1.0),
        size=1.0)
    add(ops.primitive_cube_add, "Box", material("Box", (0.2, 0.4, 0.75)),
        (0.35, 0.5, 0.15), rotation=(0.0, 0.0, math.radians(25.0)), size=0.3)
    corner = material("Corner", (0.75, 0.75, 0.7))
    add(ops.primitive_cube_add, "CornerA", corner, (-0.7, 1.2, 0.15),
        scale=(0.5, 0.06, 0.3), size=1.0)
    add(ops.primitive_cube_add, "CornerB", corner, (-0.92, 0.95, 0.15),
        scale=(0.06, 0.45, 0.3), size=1.0)
    add(ops.primitive_cylinder_add, "Cylinder", material("Cylinder", (0.3, 0.65, 0.3)),
        (0.62, -0.1, 0.25), radius=0.1, depth=0.5, vertices=48)
    sphere = add(ops.primitive_uv_sphere_add, "Sphere", material("Sphere", (0.8, 0.75, 0.2)),
                 (-0.25, -0.5, 0.12), radius=0.12, segments=48, ring_count=24)
    bpy.ops.object.shade_smooth()
    return sphere


def keyframe_linear(obj, start, step, frames=(1, 5)):
    """Key obj.location at frames[0] and frames[1]; linear interpolation and extrapolation."""
    for f in frames:
        obj.location = [s + d * (f - 1) for s, d in zip(start, step)]
        obj.keyframe_insert("location", frame=f)
    for fc in obj.animation_data.action.fcurves:
        fc.extrapolation = "LINEAR"
        for kp in fc.keyframe_points:
            kp.interpolation = "LINEAR"


def build_mover():
    """The small red sphere that moves right and up."""
    bpy.ops.mesh.primitive_uv_sphere_add(radius=MOVER_RADIUS, segments=48, ring_count=24,
                                         location=MOVER_START)
    obj = bpy.context.active_object
    obj.name = "Mover"
    obj.data.materials.append(material("Mover", (0.85, 0.1, 0.08)))
    bpy.ops.object.shade_smooth()
    keyframe_linear(obj, MOVER_START, MOVER_STEP)
    return obj


def build_camera(focus_object):
    cam_data = bpy.data.cameras.new("Camera")
    cam_data.type = "PERSP"
    cam_data.lens = 50.0
    cam_data.sensor_width = 36.0
    cam_data.sensor_height = 24.0
    cam_data.sensor_fit = "AUTO"
    cam_data.clip_start = 0.1
    cam_data.clip_end = 100.0
    cam_data.dof.use_dof = True
    cam_data.dof.focus_object = focus_object
    cam_data.dof.aperture_fstop = F_STOP
    cam = bpy.data.objects.new("Camera", cam_data)
    bpy.context.scene.collection.objects.link(cam)
    cam.rotation_euler = (math.radians(90.0 - CAMERA_TILT_DEG), 0.0, 0.0)
    keyframe_linear(cam, CAMERA_START, CAMERA_STEP)
    bpy.context.scene.camera = cam
    return cam


def build_lighting():
    sun_data = bpy.data.lights.new("Sun", type="SUN")
    sun_data.energy = 3.0
    sun_data.angle = math.radians(1.0)
    sun = bpy.data.objects.new("Sun", sun_data)
    bpy.context.scene.collection.objects.link(sun)
    sun.rotation_euler = (math.radians(40.0), 0.0, math.radians(-35.0))

    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (0.35, 0.45, 0.6, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    world.light_settings.distance = AO_DISTANCE  # radius of the AO pass
    bpy.context.scene.world = world


def configure_render(scene, width=RES_X, height=RES_Y, samples=SAMPLES):
    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.fps, r.fps_base = FPS, 1.0
    r.film_transparent = False
    r.use_motion_blur = False
    r.motion_blur_shutter = 0.5
    c = scene.cycles
    c.device = "CPU"
    c.samples = samples
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = SEED
    c.use_animated_seed = False
    c.max_bounces = 3
    c.diffuse_bounces = 2
    c.glossy_bounces = 2
    c.transmission_bounces = 2
    c.volume_bounces = 0
    c.transparent_max_bounces = 4
    c.caustics_reflective = False
    c.caustics_refractive = False
    # Pixel filter left at Blender's default: Blackman-Harris, 1.5 px.
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.frame_start, scene.frame_end = 1, 5
    im = r.image_settings
    im.file_format = "OPEN_EXR_MULTILAYER"
    im.color_depth = "32"
    im.exr_codec = "ZIP"


def set_passes(view_layer, extra, glossy=False):
    view_layer.use_pass_combined = True
    view_layer.use_pass_z = extra or glossy
    view_layer.use_pass_normal = extra or glossy
    view_layer.use_pass_vector = extra
    view_layer.use_pass_ambient_occlusion = extra
    view_layer.use_pass_glossy_direct = glossy
    view_layer.use_pass_glossy_indirect = glossy
    view_layer.use_pass_glossy_color = glossy


def make_ground_a_mirror(scene):
    """The mirror variant: a perfect white metal mirror for the ground, and bounces enough that the
    objects it reflects keep the indirect light the camera sees on them directly."""
    bsdf = bpy.data.materials["Ground"].node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    bsdf.inputs["Metallic"].default_value = 1.0
    bsdf.inputs["Roughness"].default_value = 0.0
    c = scene.cycles
    c.max_bounces = 6
    c.diffuse_bounces = 3
    c.glossy_bounces = 3


def render(scene, out_dir, variant, first, last, dof, mblur, passes, glossy=False):
    """Render frames first..last of one variant into out_dir/variant/frame_####.exr."""
    scene.camera.data.dof.use_dof = dof
    scene.render.use_motion_blur = mblur
    set_passes(bpy.context.view_layer, passes, glossy)
    keep = scene.frame_start, scene.frame_end
    scene.frame_start, scene.frame_end = first, last
    scene.render.filepath = os.path.join(out_dir, variant, "frame_####")
    t0 = time.perf_counter()
    bpy.ops.render.render(animation=True)
    print("render %s: %.1f s" % (variant, time.perf_counter() - t0), flush=True)
    scene.frame_start, scene.frame_end = keep


def main():
    args = parse_args()
    out_dir = os.path.abspath(args.out)
    os.makedirs(out_dir, exist_ok=True)
    clear_scene()
    scene = bpy.context.scene
    focus = build_geometry()
    build_mover()
    build_camera(focus)
    build_lighting()
    configure_render(scene, args.width, args.height, args.samples)
    scene.frame_set(args.first)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out_dir, "scene.blend"))

    mid = EFFECT_FRAME
    if args.variant in ("passes", "all"):
        render(scene, out_dir, "passes", args.first, args.last, dof=False, mblur=False, passes=True)
    if args.variant in ("dof", "all"):
        render(scene, out_dir, "dof", mid, mid, dof=True, mblur=False, passes=False)
    if args.variant in ("mblur", "all"):
        render(scene, out_dir, "mblur", mid, mid, dof=False, mblur=True, passes=False)
    if args.variant in ("mirror", "all"):  # last: it changes the ground's material
        make_ground_a_mirror(scene)
        render(scene, out_dir, "mirror", mid, mid, dof=False, mblur=False, passes=False, glossy=True)


if __name__ == "__main__":
    try:
        main()
    except Exception:  # Blender would print the traceback and still exit with status 0
        import traceback
        traceback.print_exc()
        sys.exit(1)
