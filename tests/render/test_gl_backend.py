import wmr_mujoco
from wmr_mujoco.render import gl_backend


def test_egl_renders_here():
    """CI machines render through Mesa's EGL (installed by scripts/install-system-deps.sh)."""
    assert gl_backend.probe("egl") is None


def test_no_backend_is_a_clear_error(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", None)
    monkeypatch.setattr(gl_backend.sys, "modules", {})
    monkeypatch.setattr(gl_backend, "probe", lambda backend: f"{backend} missing")
    try:
        gl_backend.select_backend()
    except gl_backend.RenderingUnavailableError as err:
        assert "apt-get install libegl1" in str(err) and "osmesa: osmesa missing" in str(err)
    else:
        raise AssertionError("expected RenderingUnavailableError")


def test_falls_back_to_osmesa(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", None)
    monkeypatch.setattr(gl_backend.sys, "modules", {})
    monkeypatch.setattr(gl_backend, "probe", lambda b: None if b == "osmesa" else "no EGL")
    monkeypatch.setenv("MUJOCO_GL", "egl")
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)  # restored after the test
    assert gl_backend.select_backend() == "osmesa"
    assert gl_backend.os.environ["MUJOCO_GL"] == "osmesa"
    assert gl_backend.os.environ["PYOPENGL_PLATFORM"] == "osmesa"


def test_user_choice_is_respected(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", "osmesa")
    assert gl_backend.select_backend() == "osmesa"
