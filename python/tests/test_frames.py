"""Frames as arrays: worlds drawn headless into (H, W, 3) uint8 arrays, PNG and MP4 files."""

import shutil

import numpy
import pytest

import minkowski as mk

BACKGROUND = (28, 31, 38)  # the render layer's frame colour, (0.11, 0.12, 0.15)


def scene():
    world = mk.World()
    ground = world.create_body("static")
    ground.add_box(5, 0.5)
    ball = world.create_body("dynamic", position=(0, 3))
    ball.add_circle(1.0)
    return world


def test_render_gives_an_rgb_array_of_the_world():
    world = scene()
    renderer = mk.Renderer(160, 120)
    frame = renderer.render(world)
    assert frame.shape == (120, 160, 3) and frame.dtype == numpy.uint8
    assert tuple(frame[0, 0]) == BACKGROUND
    # The camera fits the world's box: the ball's centre is drawn, not background.
    x, y = (int(v) for v in renderer.world_to_pixel((0, 3)))
    assert tuple(frame[y, x]) != BACKGROUND
    assert 0 < x < 160 and 0 < y < 120
    # Once fitted the camera stays: the fallen ball is elsewhere in the next frame.
    world.step(60)
    assert not numpy.array_equal(renderer.render(world), frame)
    renderer.follow((100, 100), 10)
    assert numpy.all(renderer.render(world) == numpy.array(BACKGROUND, dtype=numpy.uint8))
    with pytest.raises(mk.InvalidArgumentError, match="layer 'shape' is not one of"):
        renderer.render(world, layers=["shape"])


def test_frames_save_as_png_and_mp4(tmp_path):
    world = scene()
    renderer = mk.Renderer(96, 64)
    frame = renderer.render(world, overlay="hello")
    mk.save_png(tmp_path / "frame.png", frame)
    back = mk.read_png(tmp_path / "frame.png")
    assert back.shape == (64, 96, 4)
    numpy.testing.assert_array_equal(back[:, :, :3], frame)
    assert numpy.all(back[:, :, 3] == 255)
    if shutil.which("ffmpeg") is None:
        pytest.skip("ffmpeg is not installed")
    with mk.VideoWriter(tmp_path / "run.mp4", 96, 64, fps=30) as video:
        for _ in range(5):
            world.step()
            video.write(renderer.render(world))
        assert video.frames == 5
    assert (tmp_path / "run.mp4").stat().st_size > 0
    with pytest.raises(mk.InvalidArgumentError):
        mk.save_png(tmp_path / "bad.png", numpy.zeros((4, 4), dtype=numpy.uint8))


def test_an_unwritable_file_is_an_output_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(mk.OutputError) as raised:
        mk.save_png(blocker / "frame.png", numpy.zeros((4, 4, 3), dtype=numpy.uint8))
    assert str(blocker) in str(raised.value)
    assert isinstance(raised.value, OSError)
