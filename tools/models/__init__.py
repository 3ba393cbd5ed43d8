"""Generator of the demo's stand-in OBJ models and loader test fixtures (tools/make_models.py)."""
