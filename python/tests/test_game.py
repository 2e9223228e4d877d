"""The game's rules from Python: board arrays, rounds, bots, previews."""

import numpy as np
import onemorebrick


def test_a_round_moves_the_board_down_one_row():
    game = onemorebrick.Game(3)
    before = game.board()
    assert before.dtype == np.int32 and before.shape == (game.rows, game.columns, 2)
    assert game.phase == "aiming" and game.level == 1
    report = game.play(game.aim_for(0.0))
    after = game.board()
    assert game.level == 2 and report["level"] == 1 and report["balls"] == 1
    assert game.score == report["damage"]
    # What was in the top row moved down a row, less the damage done (hit points never grow).
    top = before[-1]
    moved = after[-2]
    bricks = top[:, 0] == 1
    assert np.all(moved[bricks, 1] <= top[bricks, 1])


def test_preview_reports_what_the_shot_will_do():
    game = onemorebrick.Game(8)
    aim = game.aim_for(0.6)
    predicted = game.preview(aim)
    assert game.level == 1
    assert game.play(aim) == predicted


def test_bots_choose_legal_aims():
    game = onemorebrick.Game(4)
    random_bot, greedy = onemorebrick.RandomBot(1), onemorebrick.GreedyBot(8)
    t = game.min_elevation_tan
    for bot in (random_bot, greedy, random_bot):
        dx, dy = bot.choose(game)
        assert dy >= t * abs(dx) > 0 or dx == 0
        game.play((dx, dy))
    assert game.level == 4


def test_aim_preview_and_balls_in_flight():
    game = onemorebrick.Game(2)
    path = game.aim_preview((0.0, 1.0), 2)
    assert path.shape == (3, 2)
    assert path[0, 0] == game.launch_x
    # Straight up: the first contact is right above the launcher.
    assert path[1, 0] == game.launch_x
    game.shoot((0.0, 1.0))
    assert game.advance_to(0.05) is None
    centres, radii = game.balls_in_flight()
    assert centres.shape == (1, 2) and radii.tolist() == [0.15]
    assert centres[0, 1] == 0.15 + 10.0 * 0.05
