"""The located(Name, X, Y, Yaw) literal."""
import math

import pytest

from robot_guide.locate import Located
from robot_guide.perception import located_literal


@pytest.mark.parametrize('located, text', [
    (Located('faulty', 1.50234, -0.0314, 3.1359), 'located(faulty,1.502,-0.031,3.136)'),
    (Located('faulty', 2.0, -0.0001, -math.pi / 2), 'located(faulty,2,0,-1.571)'),
    (Located('r_2', -12.34567, 0.5, 0.0), 'located(r_2,-12.346,0.5,0)'),
])
def test_metres_and_radians_with_three_decimals(located, text):
    assert located_literal(located) == text


@pytest.mark.parametrize('located', [Located('Faulty', 1, 2, 0), Located('a b', 1, 2, 0),
                                     Located('faulty', float('nan'), 0, 0),
                                     Located('faulty', 0, 0, float('inf'))])
def test_what_cannot_be_a_literal_is_refused(located):
    with pytest.raises(ValueError):
        located_literal(located)
