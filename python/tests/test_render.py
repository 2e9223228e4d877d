"""The frames of ``Game.render``: the board with its numbers, checked pixel by pixel."""

import json

import numpy as np
import onemorebrick

CELL = 40
COLUMNS, ROWS = 7, 9


def game_with(cells: dict, balls: int = 1) -> onemorebrick.Game:
    """A game whose board holds ``cells`` ({(column, row): cell}) and nothing else."""
    save = json.loads(onemorebrick.Game(3).to_json())
    board = ["Empty"] * (COLUMNS * ROWS)
    for (column, row), cell in cells.items():
        board[row * COLUMNS + column] = cell
    save["state"]["board"]["cells"] = board
    save["state"]["balls"] = balls
    return onemorebrick.Game.from_json(json.dumps(save))


def square(hp: int) -> dict:
    return {"Brick": {"shape": "Square", "hp": hp}}


def crop(frame: np.ndarray, column: int, row: int) -> np.ndarray:
    """A cell's pixels (row 0 at the bottom of the board)."""
    top = (ROWS - 1 - row) * CELL
    return frame[top : top + CELL, column * CELL : (column + 1) * CELL]


def dark(pixels: np.ndarray) -> np.ndarray:
    """Where the hit points' ink is: the bricks are bright, their numbers nearly black."""
    return pixels.max(axis=-1) < 90


def inner(pixels: np.ndarray, margin: int) -> np.ndarray:
    return pixels[margin:-margin, margin:-margin]


def test_every_brick_shows_its_hit_points_centred_and_inside_it():
    game = game_with({(1, 4): square(7), (3, 4): square(8), (5, 4): square(12345), (3, 6): square(1)})
    frame = game.render(CELL)
    masks = {}
    for column, hp in ((1, 7), (3, 8), (5, 12345)):
        # Inside the brick (its seam is 5 % of a cell), only the number is dark.
        body = inner(crop(frame, column, 4), 4)
        ink = dark(body)
        assert ink.mean() > 0.03, hp
        # Nothing touches the brick's edge: the number fits.
        assert not ink[:2].any() and not ink[-2:].any(), hp
        assert not ink[:, :2].any() and not ink[:, -2:].any(), hp
        ys, xs = np.nonzero(ink)
        centre = (body.shape[0] - 1) / 2
        assert abs(xs.mean() - centre) < 2.5 and abs(ys.mean() - centre) < 3.5, hp
        masks[hp] = ink
    assert (masks[7] != masks[8]).sum() > 20
    # Five digits are shortened ("12.3k") and as tall as they can be in the width.
    assert dark(inner(crop(frame, 3, 6), 4)).any()
    rows = np.nonzero(masks[12345].any(axis=1))[0]
    assert rows.max() - rows.min() >= 6


def test_a_triangles_number_sits_at_its_centroid_inside_it():
    triangle = {"Brick": {"shape": {"Triangle": "BottomLeft"}, "hp": 5}}
    frame = game_with({(2, 4): triangle}).render(CELL)
    pixels = crop(frame, 2, 4)
    ink = dark(pixels)
    # The board around the triangle is dark too: keep the dark pixels enclosed by bright ones
    # on both sides of their row (inside the brick).
    bright = pixels.max(axis=-1) > 150
    enclosed = np.zeros_like(ink)
    for y in range(CELL):
        xs = np.nonzero(bright[y])[0]
        if len(xs):
            enclosed[y, xs.min() : xs.max() + 1] = ink[y, xs.min() : xs.max() + 1]
    assert enclosed.sum() > 15
    ys, xs = np.nonzero(enclosed)
    # The bottom-left triangle's corners (in pixels, y down): (0, 40), (40, 40), (0, 0) or
    # the other two; either way the number is off the cell's centre toward one corner.
    centre = np.array([xs.mean(), ys.mean()])
    assert np.linalg.norm(centre - (CELL - 1) / 2) > 0.2 * CELL


def test_the_launcher_shows_the_ball_count():
    few = game_with({}, balls=1).render(CELL)
    many = game_with({}, balls=25).render(CELL)
    # The launcher is at x = 3.5 cells: its count is written beside it, in the bottom row.
    bottom = slice((ROWS - 1) * CELL, ROWS * CELL)
    text = lambda f: f[bottom, 4 * CELL :].min(axis=-1) > 200  # noqa: E731
    assert text(few).sum() > 20 and text(many).sum() > text(few).sum()
    assert (text(few) != text(many)).sum() > 20


def test_frames_are_deterministic_and_follow_the_cell_size():
    game = onemorebrick.Game(11)
    for _ in range(3):
        game.play(game.aim_for(0.4))
    first = game.render(CELL)
    again = onemorebrick.Game.from_json(game.to_json()).render(CELL)
    assert np.array_equal(first, again)
    assert game.render(20).shape == (ROWS * 20, COLUMNS * 20, 3)
