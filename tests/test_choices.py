"""Enumerated choices at the public edge: members or their string values, else a clear error."""

import enum

import pytest

from wmr_mujoco.choices import match_name, parse_choice


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


NAMES = ["disc", "disc_free", "diffdrive", "omni3", "translate 45°", "translate 315°"]


@pytest.mark.parametrize("typed, meant", [
    ("disc", "disc"),                    # exact, though a prefix of disc_free too
    ("OMNI3", "omni3"),                  # any case
    ("om", "omni3"),                     # a unique prefix
    ("translate 45", "translate 45°"),   # the degree sign optional
    ("Translate  45°", "translate 45°"),  # repeated spaces
])
def test_a_name_typed_loosely_is_found(typed, meant):
    assert match_name(typed, NAMES, "robot") == meant


def test_an_ambiguous_prefix_lists_the_names_it_begins():
    with pytest.raises(ValueError, match=r"robot 'di' is ambiguous: it begins 'disc', "
                                         r"'disc_free', 'diffdrive'"):
        match_name("di", NAMES, "robot")


def test_a_misspelling_gets_the_nearest_names_then_the_valid_ones():
    with pytest.raises(ValueError, match=r"unknown robot 'omin3'; did you mean 'omni3'\? "
                                         r"valid robots are: disc, "):
        match_name("omin3", NAMES, "robot")


def test_a_non_string_is_unknown():
    with pytest.raises(ValueError, match=r"unknown robot 3; valid robots are"):
        match_name(3, NAMES, "robot")
