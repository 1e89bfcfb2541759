"""A stand-in for exporters/blender/render_gltf.py (XVAL_BLENDER_SCRIPT) that
runs the real script but kills its own Blender process (SIGKILL) when it
starts a scene whose glTF path contains $XVAL_KILL_ON: the worker dying
mid-batch, for tests/cross/blender_worker_dies.cmake. The real script:
$XVAL_REAL_BLENDER_SCRIPT."""
import importlib.util
import os
import signal

spec = importlib.util.spec_from_file_location("render_gltf", os.environ["XVAL_REAL_BLENDER_SCRIPT"])
real = importlib.util.module_from_spec(spec)
spec.loader.exec_module(real)
render_scene = real.render_scene


def killing_render_scene(args):
    if os.environ["XVAL_KILL_ON"] in args.gltf:
        os.kill(os.getpid(), signal.SIGKILL)
    return render_scene(args)


real.render_scene = killing_render_scene
real.main()
