"""The case-study campaign (thesis chapter 7): seeded runs of faulty_helper.launch per
fault, their bags read back into step latencies and outcomes, a Markdown/JSON report and
figures; and the fault-tolerance scenario (issue 15: ``poses``, ``mission``,
``mission_report``, ``mission_figures``), each run with recovery and as the thesis's
baseline. Everything but ``runner`` and ``bagread`` works without ROS."""
from rason_campaign.plan import FAULTS, INTERACTIONS, RunSpec, make_plan
from rason_campaign.steps import Steps, classify, extract_steps

__all__ = ['FAULTS', 'INTERACTIONS', 'RunSpec', 'make_plan', 'Steps', 'classify',
           'extract_steps']
