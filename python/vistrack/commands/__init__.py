"""Sub-commands of the ``vistrack`` command line, one module each."""


def positive_numbers(flag: str, example: str):
    """An argparse type for a comma-separated list of positive numbers, e.g. --spacings 50,25."""
    import argparse

    def parse(text: str) -> list[float]:
        try:
            values = [float(v) for v in text.split(",") if v.strip()]
        except ValueError:
            values = []
        if not values or any(not (v > 0) for v in values):
            raise argparse.ArgumentTypeError(f"{flag} = {text}: need positive numbers like {example}")
        return values

    return parse
