"""PPO (stable-baselines3) on One More Brick.

Not run by the tests: stable-baselines3 pulls in PyTorch. Install and run:

    pip install ./python "stable-baselines3>=2.3"
    python python/examples/train_ppo.py --steps 200000 --envs 4 --out ppo_onemorebrick

What it does:

- builds ``--envs`` copies of ``OneMoreBrick-v0`` in subprocesses (``SubprocVecEnv``; each
  step is a whole round simulated in Rust, so processes scale it over cores), each seeded;
- trains ``MultiInputPolicy`` PPO: the observation is a dict (``board``: cell kinds and hit
  points, ``balls``, ``launcher``), which stable-baselines3 flattens and feeds to an MLP; the
  action is one aim in [-1, 1];
- every ``--eval-every`` steps, plays ``--eval-games`` games with the deterministic policy and
  with a uniformly random one, and prints the mean score of each: the agent should pull away
  from the random baseline after some 10^5 steps;
- saves the model (``--out``.zip).

The reward is the hit points taken off each round (the game's score); ``--reward bricks``
rewards bricks destroyed instead. Episodes end at game over; ``--max-rounds`` truncates
them (long games slow training down late on).
"""

import argparse

import gymnasium
import numpy as np

import onemorebrick  # noqa: F401  (registers OneMoreBrick-v0)


def evaluate(policy, games, seed):
    """Mean score over ``games`` games; ``policy(obs)`` returns an action."""
    env = gymnasium.make("OneMoreBrick-v0")
    scores = []
    for k in range(games):
        obs, info = env.reset(seed=seed + k)
        done = False
        while not done:
            obs, _, terminated, truncated, info = env.step(policy(obs))
            done = terminated or truncated
        scores.append(info["score"])
    return float(np.mean(scores))


def main():
    parser = argparse.ArgumentParser(description="PPO on OneMoreBrick-v0")
    parser.add_argument("--steps", type=int, default=200_000)
    parser.add_argument("--envs", type=int, default=4)
    parser.add_argument("--reward", choices=["damage", "bricks"], default="damage")
    parser.add_argument("--max-rounds", type=int, default=500)
    parser.add_argument("--eval-every", type=int, default=50_000)
    parser.add_argument("--eval-games", type=int, default=10)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="ppo_onemorebrick")
    args = parser.parse_args()

    from stable_baselines3 import PPO
    from stable_baselines3.common.env_util import make_vec_env
    from stable_baselines3.common.vec_env import SubprocVecEnv

    env_kwargs = {"reward": args.reward, "max_rounds": args.max_rounds}
    envs = make_vec_env(
        "OneMoreBrick-v0",
        n_envs=args.envs,
        seed=args.seed,
        vec_env_cls=SubprocVecEnv,
        env_kwargs=env_kwargs,
    )
    model = PPO("MultiInputPolicy", envs, n_steps=256, batch_size=256, seed=args.seed, verbose=0)
    rng = np.random.default_rng(args.seed)
    random_policy = lambda obs: rng.uniform(-1, 1, size=1).astype(np.float32)  # noqa: E731
    agent = lambda obs: model.predict(obs, deterministic=True)[0]  # noqa: E731
    done = 0
    while done < args.steps:
        chunk = min(args.eval_every, args.steps - done)
        model.learn(total_timesteps=chunk, reset_num_timesteps=False)
        done += chunk
        ppo = evaluate(agent, args.eval_games, seed=10_000)
        baseline = evaluate(random_policy, args.eval_games, seed=10_000)
        print(f"steps {done}: mean score PPO {ppo:.1f}, random {baseline:.1f}", flush=True)
    model.save(args.out)
    print(f"saved {args.out}.zip")
    envs.close()


if __name__ == "__main__":
    main()
