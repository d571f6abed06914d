"""What the examples' command lines share: bad input is one line naming the argument and
exit code 2, as crux's own CLI answers it. The examples import it from their folder (a
script's own folder is first on sys.path)."""

import argparse


class OneLineParser(argparse.ArgumentParser):
    """Bad input: one line naming the argument, exit code 2 (argparse's code, without its usage)."""

    def error(self, message):
        self.exit(2, f"{self.prog}: {message}\n")


def integer_at_least(minimum):
    """An argparse type: an integer of at least `minimum`."""

    def parse(text):
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be an integer, got {text!r}") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"must be at least {minimum}, got {value}")
        return value

    return parse


positive = integer_at_least(1)
LARGEST_SEED = 2**64 - 1  # a wall's seed is crux's 64-bit seed


def wall_seed_range(text):
    """Random walls' seeds A:B, A to B inclusive, as a range."""
    first, _, last = text.partition(":")
    if not first.isdigit() or not last.isdigit() or not int(first) <= int(last) <= LARGEST_SEED:
        raise argparse.ArgumentTypeError(f"'{text}' is not A:B with 0 <= A <= B <= {LARGEST_SEED}")
    return range(int(first), int(last) + 1)
