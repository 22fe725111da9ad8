"""Unit tests of rason_wiring.fields: message fields by path (no ROS master)."""
import pytest
from geometry_msgs.msg import PoseStamped, Polygon
from move_base_msgs.msg import MoveBaseGoal
from sensor_msgs.msg import JointState
from std_msgs.msg import Header, UInt8MultiArray

from rason_wiring import fields, terms
from rason_wiring.terms import Value


def test_field_type_follows_nested_paths():
    assert fields.field_type(MoveBaseGoal, 'target_pose.pose.position.x') == 'float64'
    assert fields.field_type(MoveBaseGoal, 'target_pose.header.frame_id') == 'string'
    assert fields.field_type(JointState, 'name') == 'string[]'


@pytest.mark.parametrize('cls, path, message', [
    (MoveBaseGoal, 'target_pose.pose.postion.x', "target_pose.pose has no field 'postion' (it has: position, orientation)"),
    (MoveBaseGoal, 'pose', "move_base_msgs/MoveBaseGoal has no field 'pose'"),
    (MoveBaseGoal, 'target_pose.pose', 'target_pose.pose is a message (geometry_msgs/Pose): name one of its fields (position, orientation)'),
    (MoveBaseGoal, 'target_pose.header.frame_id.x', 'target_pose.header.frame_id is a string: it has no fields'),
    (Header, 'stamp', 'time and duration fields are not supported'),
    (Polygon, 'points', 'is an array of messages (geometry_msgs/Point32[]): not supported'),
    (Polygon, 'points.x', 'points is a geometry_msgs/Point32[]: it has no fields'),
])
def test_field_type_names_what_is_wrong_with_a_path(cls, path, message):
    with pytest.raises(fields.BadPath, match=None) as e:
        fields.field_type(cls, path)
    assert message in str(e.value)


@pytest.mark.parametrize('ftype, value, fitted', [
    ('float64', Value('number', 2), 2.0), ('float32', Value('number', -0.5), -0.5),
    ('int32', Value('number', 7), 7), ('int32', Value('number', 7.0), 7),
    ('uint8', Value('number', 255), 255), ('int8', Value('number', -128), -128),
    ('bool', Value('atom', 'true'), True), ('bool', Value('atom', 'false'), False),
    ('string', Value('atom', 'odom'), 'odom'), ('string', Value('string', 'a b'), 'a b'),
    ('string', Value('number', 3), '3'), ('string', Value('term', 'p(1)'), 'p(1)'),
    ('float64[]', terms.parse('[1,2.5]'), [1.0, 2.5]), ('float64[2]', terms.parse('[1,2]'), [1.0, 2.0]),
    ('string[]', terms.parse('[a,"b c"]'), ['a', 'b c']), ('int32[]', terms.parse('[]'), []),
])
def test_fit_converts_values_to_the_field_type(ftype, value, fitted):
    result = fields.fit(ftype, value, 'f')
    assert result == fitted and type(result) is type(fitted)


@pytest.mark.parametrize('ftype, value, why', [
    ('float64', Value('atom', 'far'), 'a number is needed, not far'),
    ('float64', Value('string', 'x'), 'a number is needed, not "x"'),
    ('int32', Value('number', 1.5), '1.5 is not a whole number (int32)'),
    ('uint8', Value('number', 256), '256 is outside uint8 (0..255)'),
    ('uint32', Value('number', -1), '-1 is outside uint32'),
    ('int64', Value('number', 2 ** 63), 'is outside int64'),
    ('float32', Value('number', 1e39), 'does not fit a float32'),
    ('bool', Value('atom', 'yes'), 'true or false is needed, not yes'),
    ('bool', Value('number', 1), 'true or false is needed, not 1'),
    ('string', terms.parse('[a]'), 'text is needed, not a list'),
    ('float64[]', Value('number', 1), 'a list is needed, not 1'),
    ('float64[3]', terms.parse('[1,2]'), 'a list of 3 is needed, not 2 elements'),
])
def test_fit_refuses_a_value_that_does_not_fit_naming_the_field(ftype, value, why):
    with pytest.raises(fields.BadValue) as e:
        fields.fit(ftype, value, 'target.x')
    assert e.value.path == 'target.x'
    assert str(e.value).startswith('target.x: ') and why in str(e.value)


def test_fit_names_the_element_of_a_list_that_does_not_fit():
    with pytest.raises(fields.BadValue) as e:
        fields.fit('int32[]', terms.parse('[1,x]'), 'ids')
    assert e.value.path == 'ids[1]'


def test_fill_and_read_nested_fields():
    msg = PoseStamped()
    fields.fill(msg, 'pose.position.y', 2.5)
    fields.fill(msg, 'header.frame_id', 'odom')
    assert msg.pose.position.y == 2.5 and msg.header.frame_id == 'odom'
    assert fields.read(msg, 'pose.position.y') == 2.5


def test_uint8_arrays_are_filled_from_lists():
    msg = UInt8MultiArray()
    fields.fill(msg, 'data', fields.fit('uint8[]', terms.parse('[1,2]'), 'data'))
    assert list(msg.data) == [1, 2]
