"""Offscreen rendering (EGL, else OSMesa), videos with trails, and the interactive viewer."""
