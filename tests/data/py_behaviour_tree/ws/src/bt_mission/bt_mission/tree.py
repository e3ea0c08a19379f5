"""Builds the mission tree out of the behaviours; knows nothing about the node."""

import py_trees

from bt_mission.behaviours import BatteryCheck, CallTrigger, NavigateTo, PublishGoal


def battery_checks():
    return py_trees.composites.Parallel(
        name='Batteries',
        policy=py_trees.common.ParallelPolicy.SuccessOnAll(),
        children=[
            BatteryCheck('Main battery', topic_name='/battery/state'),
            BatteryCheck('Backup battery', '/backup_battery/state', 0.1),
        ],
    )


def create_root(robot):
    drive = py_trees.composites.Sequence(name='Drive', memory=True)
    drive.add_children([PublishGoal('Goal', robot=robot), NavigateTo('Navigate')])
    return py_trees.composites.Sequence(
        name='Mission',
        memory=True,
        children=[battery_checks(), drive, CallTrigger('Dock', 'docking', 'start')],
    )
