"""Tools of the rason package for people and tests watching a run: ``rason_dialogue``
(:mod:`rason_tools.dialogue` formats, :mod:`rason_tools.dialogue_node` is the node) and
``fake_robot.py`` (:mod:`rason_tools.fake_robot`, a scripted decomposer and synthesizer).
Only :mod:`rason_tools.dialogue` works without rospy."""
