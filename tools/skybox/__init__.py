"""Generator of the cube-map skybox test images (tools/make_skybox.py)."""
