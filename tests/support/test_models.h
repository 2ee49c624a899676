#pragma once
// Small models written for tests: a branching tree with every joint type the loader supports.
#include <string>

namespace stanceplan::test {

// Root "base" (box), a 4-joint arm with revolute axes along x, y, z and a tilted one, a prismatic
// joint, a fixed joint, and a second branch whose joint mimics the first arm joint (x -2, +0.1).
inline const char* kBranchingUrdf = R"(<?xml version="1.0"?>
<robot name="branching">
  <link name="base">
    <inertial><origin xyz="0.01 0.02 0.03"/><mass value="3.0"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision>
  </link>
  <link name="a1"><inertial><origin xyz="0 0 0.1"/><mass value="1.0"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="a2"><inertial><origin xyz="0.05 0 0.1"/><mass value="0.8"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="a3"><inertial><origin xyz="0 0.05 0.1"/><mass value="0.6"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="a4"><inertial><origin xyz="0.02 0.01 0.05"/><mass value="0.4"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="slider"><inertial><mass value="0.3"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="tool"><inertial><origin xyz="0 0 0.02"/><mass value="0.2"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="b1"><inertial><origin xyz="0 0.1 0"/><mass value="0.5"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="a1"/>
    <origin xyz="0.1 0 0.05" rpy="0.1 0.2 0.3"/><axis xyz="1 0 0"/>
    <limit lower="-2" upper="2" effort="50" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a1"/><child link="a2"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="40" velocity="1"/></joint>
  <joint name="j3" type="continuous"><parent link="a2"/><child link="a3"/>
    <origin xyz="0.05 0 0.2" rpy="0 0.4 0"/><axis xyz="0 0 1"/>
    <limit effort="30" velocity="1"/></joint>
  <joint name="j4" type="revolute"><parent link="a3"/><child link="a4"/>
    <origin xyz="0 0.05 0.2" rpy="0.3 0 0"/><axis xyz="1 1 1"/>
    <limit lower="-1" upper="1" effort="20" velocity="1"/></joint>
  <joint name="p5" type="prismatic"><parent link="a4"/><child link="slider"/>
    <origin xyz="0 0 0.1" rpy="0 0 0.5"/><axis xyz="0 0.6 0.8"/>
    <limit lower="0" upper="0.2" effort="100" velocity="1"/></joint>
  <joint name="f6" type="fixed"><parent link="slider"/><child link="tool"/>
    <origin xyz="0.03 0 0.05" rpy="0 0.5 0"/></joint>
  <joint name="m7" type="revolute"><parent link="base"/><child link="b1"/>
    <origin xyz="-0.1 0.1 0" rpy="0 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/>
    <mimic joint="j1" multiplier="-2" offset="0.1"/></joint>
</robot>
)";

}  // namespace stanceplan::test
