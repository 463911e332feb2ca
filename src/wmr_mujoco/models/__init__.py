"""The robots as MuJoCo models: parameters, builders, files, loading, actuation, export."""
