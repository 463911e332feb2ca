"""Enumerated choices at the public edge: members or their string values, else a clear error."""

import enum

import pytest

from wmr_mujoco.choices import parse_choice


class Colour(str, enum.Enum):
    RED = "red"
    BLUE = "blue"


def test_member_and_value_give_the_member():
    assert parse_choice(Colour, Colour.BLUE, "colour") is Colour.BLUE
    assert parse_choice(Colour, "red", "colour") is Colour.RED


def test_unknown_value_names_it_and_the_valid_ones():
    with pytest.raises(ValueError, match=r"unknown colour 'green'; valid colours are: red, "
                                         r"blue$"):
        parse_choice(Colour, "green", "colour")
