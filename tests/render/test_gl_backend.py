import pytest

import wmr_mujoco
from wmr_mujoco.gl_env import GLChoice
from wmr_mujoco.render import gl_backend

#: The process as wmr_mujoco.gl_env leaves it where EGL's library is found.
EGL_FOUND = GLChoice(None, "egl", None)


@pytest.mark.gl
def test_the_chosen_backend_renders_here():
    """Where a backend was found (Mesa's EGL on the CI image), it draws a frame."""
    assert gl_backend.probe(gl_backend.select_backend()) is None


def test_no_backend_is_a_clear_error(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", None)
    monkeypatch.setattr(wmr_mujoco, "GL", EGL_FOUND)
    monkeypatch.setattr(gl_backend, "mujoco_imported", lambda: False)
    monkeypatch.setattr(gl_backend, "probe", lambda backend: f"{backend} missing")
    try:
        gl_backend.select_backend()
    except gl_backend.RenderingUnavailableError as err:
        assert "apt-get install libegl1" in str(err) and "osmesa: osmesa missing" in str(err)
    else:
        raise AssertionError("expected RenderingUnavailableError")


def test_falls_back_to_osmesa(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", None)
    monkeypatch.setattr(wmr_mujoco, "GL", EGL_FOUND)
    monkeypatch.setattr(gl_backend, "mujoco_imported", lambda: False)
    monkeypatch.setattr(gl_backend, "probe", lambda b: None if b == "osmesa" else "no EGL")
    monkeypatch.setenv("MUJOCO_GL", "egl")
    monkeypatch.delenv("PYOPENGL_PLATFORM", raising=False)  # restored after the test
    assert gl_backend.select_backend() == "osmesa"
    assert gl_backend.os.environ["MUJOCO_GL"] == "osmesa"
    assert gl_backend.os.environ["PYOPENGL_PLATFORM"] == "osmesa"


def test_user_choice_is_respected(monkeypatch):
    monkeypatch.setattr(wmr_mujoco, "USER_MUJOCO_GL", "osmesa")
    monkeypatch.setattr(wmr_mujoco, "GL", GLChoice("osmesa", "osmesa", None))
    assert gl_backend.select_backend() == "osmesa"


def test_a_user_backend_that_cannot_load_is_refused_with_its_reason(monkeypatch):
    problem = "MUJOCO_GL=osmesa was asked for, but libOSMesa is not installed"
    monkeypatch.setattr(wmr_mujoco, "GL", GLChoice("osmesa", "disable", problem))
    with pytest.raises(gl_backend.RenderingUnavailableError, match="libOSMesa is not"):
        gl_backend.select_backend()
