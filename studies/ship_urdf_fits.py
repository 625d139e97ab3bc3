"""Write the fitted capsules and allowed-collision matrices of the shipped URDF arms into
``moik/collision/data/urdf`` (read before the user's cache by
:func:`moik.collision.mesh_fit.load_cached`), so that a first collision-aware solve of
``load_urdf(<shipped URDF>, package_dirs=<shipped packages>)`` or of a catalog arm's
``robot_model`` neither fits nor samples (nor compiles the exact stage to sample); the
panda with its fingers open (``joint_values={"panda_finger_joint1": 0.04}``) too.

The files are named by the digest of what they depend on (mesh bytes, poses, settings),
so a change of any input is simply not found there and computed as for any URDF.

    python -m studies.ship_urdf_fits
"""

from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["XDG_CACHE_HOME"] = tmp  # an empty cache: every file is computed here
        from moik.collision import mesh_fit
        from moik.collision.urdf import robot_model
        from moik.robots import get_robot

        out = mesh_fit.SHIPPED
        mesh_fit.SHIPPED = Path(tmp, "none")  # nothing read from the shipped folder: all anew
        for name in ("panda", "ur5", "iiwa14"):
            robot_model(get_robot(name))
        # the panda's fingers open as well as closed (their default): its two placements
        robot_model(get_robot("panda"), joint_values={"panda_finger_joint1": 0.04})
        out.mkdir(parents=True, exist_ok=True)
        for old in out.glob("*.json"):
            old.unlink()
        for path in sorted(Path(tmp, "moik", "collision").glob("*.json")):
            shutil.copy(path, out / path.name)
            print(f"{out / path.name}")


if __name__ == "__main__":
    main()
