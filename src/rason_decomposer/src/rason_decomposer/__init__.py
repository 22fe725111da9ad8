"""rason_decomposer: what every Rason decomposer needs to take, announce, answer and cancel
its actions.

:mod:`rason_decomposer.book` is the bookkeeping without rospy (:class:`~book.ActionBook`);
:mod:`rason_decomposer.node` is the rospy side (:class:`~node.Decomposer`; import it only
where rospy is available).
"""
